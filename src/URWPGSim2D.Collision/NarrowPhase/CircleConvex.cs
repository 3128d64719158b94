using System;
using System.Numerics;
using URWPGSim2D.Collision.Geometry;
using URWPGSim2D.Collision.Shapes;

namespace URWPGSim2D.Collision.NarrowPhase;

/// <summary>
/// Circle against any convex polygon-like view by Voronoi regions. The edge of greatest
/// separation s = n·(c − v) is found in one pass; when s ≤ 0 the centre is inside and the MTV
/// leaves through that edge (depth r − s); otherwise the centre lies in the region of that edge
/// or of one of its two end vertices (decided by two dot products, no angles), which is exact
/// for convex polygons.
/// </summary>
internal static class CircleConvex
{
    /// <summary>The MTV moves the circle; its normal points from the polygon toward the circle.</summary>
    public static CollisionDetectionResult Detect(in Circle circle, in ConvexView polygon)
    {
        Vector2 c = circle.Center;
        float r = circle.Radius;
        var v = polygon.Vertices;
        var nrm = polygon.Normals;
        Vector2 normal;
        float depth;
        if (v.Length == 1)
        {
            if (!PointRegion(c, r, v[0], out normal, out depth))
            {
                return CollisionDetectionResult.None;
            }
        }
        else
        {
            int edge = 0;
            float maxSep = float.NegativeInfinity;
            for (int i = 0; i < v.Length; i++)
            {
                float s = Vector2.Dot(nrm[i], c - v[i]);
                if (s >= r)
                {
                    return CollisionDetectionResult.None;
                }

                if (s > maxSep)
                {
                    maxSep = s;
                    edge = i;
                }
            }

            Vector2 v1 = v[edge];
            Vector2 v2 = v[edge + 1 == v.Length ? 0 : edge + 1];
            if (maxSep <= 0f && v.Length >= 3)
            {
                normal = nrm[edge];
                depth = r - maxSep;
            }
            else if (Vector2.Dot(c - v1, v2 - v1) <= 0f)
            {
                if (!PointRegion(c, r, v1, out normal, out depth))
                {
                    return CollisionDetectionResult.None;
                }
            }
            else if (Vector2.Dot(c - v2, v1 - v2) <= 0f)
            {
                if (!PointRegion(c, r, v2, out normal, out depth))
                {
                    return CollisionDetectionResult.None;
                }
            }
            else
            {
                normal = nrm[edge];
                depth = r - maxSep;
            }
        }

        return CollisionDetectionResult.FromPlane(normal, depth, ActionPoint(polygon, c, r, normal, depth));
    }

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
