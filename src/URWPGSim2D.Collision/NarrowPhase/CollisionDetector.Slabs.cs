using URWPGSim2D.Collision.NarrowPhase;

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

    /// <summary>
    /// Box against box: interval overlap on x and z only (the Minkowski difference of two boxes is
    /// a box, so these two axes are exact, and their float differences are exact too); the MTV is
    /// the least of the four one-sided overlaps; the action point is the centre of the
    /// intersection rectangle.
    /// </summary>
    /// <param name="a">The box moved by the MTV.</param>
    /// <param name="b">The other box.</param>
    /// <returns>The contact, or <see cref="CollisionDetectionResult.None"/>.</returns>
    public static CollisionDetectionResult Detect(in Aabb a, in Aabb b)
    {
        Vector2 forward = b.Max - a.Min;
        Vector2 backward = a.Max - b.Min;
        if (!(forward.X > 0f && forward.Y > 0f && backward.X > 0f && backward.Y > 0f))
        {
            return CollisionDetectionResult.None;
        }

        float depth = forward.X;
        Vector2 normal = Vector2.UnitX;
        if (backward.X < depth)
        {
            depth = backward.X;
            normal = -Vector2.UnitX;
        }

        if (forward.Y < depth)
        {
            depth = forward.Y;
            normal = Vector2.UnitY;
        }

        if (backward.Y < depth)
        {
            depth = backward.Y;
            normal = -Vector2.UnitY;
        }

        Vector2 centre = (Vector2.Max(a.Min, b.Min) + Vector2.Min(a.Max, b.Max)) * 0.5f;
        return CollisionDetectionResult.FromPlane(normal, depth, centre);
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
