using System;
using System.Numerics;
using URWPGSim2D.Collision.Geometry;
using URWPGSim2D.Collision.Shapes;

namespace URWPGSim2D.Collision.Benchmarks.Baseline.NarrowPhase;

/// <summary>
/// Circle against any convex polygon-like view by Voronoi regions. The edge of greatest
/// separation s = n·(c − v) is found in one pass (four edges at a time, see
/// <see cref="FaceLoops.Farthest"/>); when s ≤ 0 the centre is inside and the MTV
/// leaves through that edge (depth r − s); otherwise the centre lies in the region of that edge
/// or of one of its two end vertices (decided by two dot products, no angles), which is exact
/// for convex polygons.
/// </summary>
internal static class CircleConvex
{
    /// <summary>The MTV moves the circle; its normal points from the polygon toward the circle.</summary>
    public static CollisionDetectionResult Detect(in Circle circle, in ConvexView polygon) =>
        Depth(circle, polygon, out ContactDepth depth) ? Complete(circle, polygon, depth) : CollisionDetectionResult.None;

    /// <summary>Whether the circle and the polygon overlap and, if so, the normal and depth (no action point).</summary>
    public static bool Depth(in Circle circle, in ConvexView polygon, out ContactDepth depth)
    {
        Vector2 c = circle.Center;
        float r = circle.Radius;
        var v = polygon.Vertices;
        var nrm = polygon.Normals;
        Vector2 normal;
        float distance;
        depth = default;
        if (v.Length == 1)
        {
            if (!PointRegion(c, r, v[0], out normal, out distance))
            {
                return false;
            }
        }
        else
        {
            if (!FaceLoops.Farthest(v, nrm, c, r, out int edge, out float maxSep))
            {
                return false;
            }

            Vector2 v1 = v[edge];
            Vector2 v2 = v[edge + 1 == v.Length ? 0 : edge + 1];
            if (maxSep <= 0f && v.Length >= 3)
            {
                normal = nrm[edge];
                distance = r - maxSep;
            }
            else if (Vector2.Dot(c - v1, v2 - v1) <= 0f)
            {
                if (!PointRegion(c, r, v1, out normal, out distance))
                {
                    return false;
                }
            }
            else if (Vector2.Dot(c - v2, v1 - v2) <= 0f)
            {
                if (!PointRegion(c, r, v2, out normal, out distance))
                {
                    return false;
                }
            }
            else
            {
                normal = nrm[edge];
                distance = r - maxSep;
            }
        }

        depth = new ContactDepth(normal, distance);
        return true;
    }

    /// <summary>The finished contact for a <paramref name="depth"/> that <see cref="Depth"/> found for the same circle and polygon.</summary>
    public static CollisionDetectionResult Complete(in Circle circle, in ConvexView polygon, in ContactDepth depth) =>
        CollisionDetectionResult.FromPlane(depth.Normal, depth.Depth, ActionPoint(polygon, circle.Center, circle.Radius, depth.Normal, depth.Depth));

    // Circle against a single vertex: overlap when |c − p| < r, pushed along (c − p).
    private static bool PointRegion(Vector2 c, float r, Vector2 p, out Vector2 normal, out float depth)
    {
        Vector2 d = c - p;
        float dist2 = d.LengthSquared();
        if (dist2 >= r * r)
        {
            normal = default;
            depth = 0f;
            return false;
        }

        float dist = MathF.Sqrt(dist2);
        normal = dist > 0f ? d / dist : Vector2.UnitX;
        depth = r - dist;
        return true;
    }

    // The middle of the overlap of the circle and the polygon on the line c + t·normal.
    private static Vector2 ActionPoint(in ConvexView polygon, Vector2 c, float r, Vector2 normal, float depth)
    {
        ContactRegion.LineInterval(polygon, c, normal, out float lo, out float hi);
        lo = MathF.Max(lo, -r);
        hi = MathF.Min(hi, r);
        float t = lo <= hi ? 0.5f * (lo + hi) : Math.Clamp(depth - r, -r, r);
        return c + normal * t;
    }
}
