using System.Numerics;
using URWPGSim2D.Collision.NarrowPhase;
using URWPGSim2D.Collision.Shapes;

namespace URWPGSim2D.Collision;

/// <content>Boxes and 8-DOPs against each other, by the fixed-axis slab test <see cref="SlabSat"/>.</content>
public static partial class CollisionDetector
{
    /// <summary>
    /// 8-DOP against 8-DOP: interval overlap on the four fixed axes; the MTV is the least of the
    /// eight one-sided overlaps; the action point is the centroid of the intersection 8-DOP.
    /// </summary>
    /// <param name="a">The 8-DOP moved by the MTV.</param>
    /// <param name="b">The other 8-DOP.</param>
    /// <returns>The contact, or <see cref="CollisionDetectionResult.None"/>.</returns>
    public static CollisionDetectionResult Detect(in KDop8 a, in KDop8 b) => SlabSat.Detect(a.MinSlabs, a.MaxSlabs, b.MinSlabs, b.MaxSlabs);

    /// <summary>Box against box: the slab test (the diagonal slabs of two boxes never decide the MTV).</summary>
    /// <param name="a">The box moved by the MTV.</param>
    /// <param name="b">The other box.</param>
    /// <returns>The contact, or <see cref="CollisionDetectionResult.None"/>.</returns>
    public static CollisionDetectionResult Detect(in Aabb a, in Aabb b)
    {
        SlabSat.Of(a, out Vector4 minA, out Vector4 maxA);
        SlabSat.Of(b, out Vector4 minB, out Vector4 maxB);
        return SlabSat.Detect(minA, maxA, minB, maxB);
    }

    /// <summary>Box against 8-DOP: the box as an 8-DOP, then the slab test.</summary>
    /// <param name="a">The box, moved by the MTV.</param>
    /// <param name="b">The 8-DOP.</param>
    /// <returns>The contact, or <see cref="CollisionDetectionResult.None"/>.</returns>
    public static CollisionDetectionResult Detect(in Aabb a, in KDop8 b)
    {
        SlabSat.Of(a, out Vector4 minA, out Vector4 maxA);
        return SlabSat.Detect(minA, maxA, b.MinSlabs, b.MaxSlabs);
    }

    /// <summary>8-DOP against box: <see cref="Detect(in Aabb, in KDop8)"/> swapped.</summary>
    /// <param name="a">The 8-DOP, moved by the MTV.</param>
    /// <param name="b">The box.</param>
    /// <returns>The contact, or <see cref="CollisionDetectionResult.None"/>.</returns>
    public static CollisionDetectionResult Detect(in KDop8 a, in Aabb b) => Detect(b, a).Swapped();
}
