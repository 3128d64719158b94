namespace URWPGSim2D.Collision.NarrowPhase;

/// <summary>
/// The separating-axis test for two shapes given as tight slabs on the same four fixed axes
/// (8-DOPs, and boxes seen as 8-DOPs): no vertex projection at all. The overlap of two slab
/// sets is again a slab set, whose polygon gives the action point (its area centroid).
/// </summary>
internal static class SlabSat
{
    /// <summary>The MTV moves shape a (slabs minA..maxA).</summary>
    public static CollisionDetectionResult Detect(Vector4 minA, Vector4 maxA, Vector4 minB, Vector4 maxB)
    {
        Vector4 forward = maxB - minA;
        Vector4 backward = maxA - minB;
        if (!Vector4.GreaterThanAll(forward, Vector4.Zero) || !Vector4.GreaterThanAll(backward, Vector4.Zero))
        {
            return CollisionDetectionResult.None;
        }

        float depth = float.PositiveInfinity;
        Vector2 normal = default;
        for (int i = 0; i < 4; i++)
        {
            if (forward[i] < depth)
            {
                depth = forward[i];
                normal = KDop8.Axis(i);
            }

            if (backward[i] < depth)
            {
                depth = backward[i];
                normal = -KDop8.Axis(i);
            }
        }

        Vector2 point = KDop8Vertices.RegionCentroid(Vector4.Max(minA, minB), Vector4.Min(maxA, maxB), out Vector2 centroid)
            ? centroid
            : new Vector2(0.5f * (MathF.Max(minA.X, minB.X) + MathF.Min(maxA.X, maxB.X)), 0.5f * (MathF.Max(minA.Y, minB.Y) + MathF.Min(maxA.Y, maxB.Y)));
        return CollisionDetectionResult.FromPlane(normal, depth, point);
    }

    /// <summary>The four slabs of a box: x, z, and the diagonals through its corners.</summary>
    public static void Of(in Aabb box, out Vector4 min, out Vector4 max) => KDop8.SlabsOf(box, out min, out max);
}
