using System;
using System.Numerics;
using URWPGSim2D.Collision.Geometry;

namespace URWPGSim2D.Collision.NarrowPhase;

/// <summary>
/// The separating-axis test with minimum translation vector for two convex polygon-like views.
/// Both shapes are projected on every axis of either; an axis on which the projections do not
/// overlap (or only touch) separates them. Otherwise the MTV is the smallest of the overlaps
/// maxB − minA (move a along +axis) and maxA − minB (move a along −axis) over all axes. Because
/// the edge normals of both shapes contain every edge normal of their Minkowski difference, this
/// minimum is the exact penetration depth, containment included.
/// </summary>
internal static class ConvexSat
{
    /// <summary>The MTV moves <paramref name="a"/>; all projections are taken relative to a's first vertex.</summary>
    public static CollisionDetectionResult Detect(in ConvexView a, in ConvexView b)
    {
        Vector2 origin = a.Vertices[0];
        float depth = float.PositiveInfinity;
        Vector2 normal = default;
        if (!MinimumOverlap(a.Axes, a, b, origin, ref depth, ref normal)
            || !MinimumOverlap(b.Axes, a, b, origin, ref depth, ref normal))
        {
            return CollisionDetectionResult.None;
        }

        Vector2 point = ContactRegion.IntersectionCentroid(a, b, origin, normal);
        return CollisionDetectionResult.FromPlane(normal, depth, point);
    }

    private static bool MinimumOverlap(ReadOnlySpan<Vector2> axes, in ConvexView a, in ConvexView b, Vector2 origin, ref float depth, ref Vector2 normal)
    {
        foreach (Vector2 axis in axes)
        {
            a.Project(axis, origin, out float minA, out float maxA);
            b.Project(axis, origin, out float minB, out float maxB);
            float forward = maxB - minA;
            float backward = maxA - minB;
            if (forward <= 0f || backward <= 0f)
            {
                return false;
            }

            if (forward < depth)
            {
                depth = forward;
                normal = axis;
            }

            if (backward < depth)
            {
                depth = backward;
                normal = -axis;
            }
        }

        return true;
    }
}
