using System;
using System.Numerics;

namespace URWPGSim2D.Collision.Tests.NarrowPhase.Frozen;

/// <summary>
/// The circle–polygon kernel as it was before issue 10's speed work (main at ad2603e; the same
/// code is kept in benchmarks/URWPGSim2D.Collision.Benchmarks/Baseline/NarrowPhase), reduced to
/// its scalar path for polygons of three or more vertices (its vector path gave the same bits).
/// The tests compare today's kernel with it: the normal and the depth must be the same bits, the
/// action point within rounding. Not maintained: do not fix or improve it.
/// </summary>
internal static class FrozenCircleConvex
{
    /// <summary>The contact of the circle (moved by the MTV) with the convex polygon (vertices counter-clockwise, outward unit edge normals).</summary>
    public static CollisionDetectionResult Detect(Vector2 c, float r, ReadOnlySpan<Vector2> v, ReadOnlySpan<Vector2> nrm)
    {
        int edge = 0;
        float maxSep = float.NegativeInfinity;
        for (int i = 0; i < nrm.Length; i++)
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
        Vector2 normal;
        float depth;
        if (maxSep <= 0f)
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

        // The middle of the overlap of the circle and the polygon on the line c + t·normal.
        float lo = float.NegativeInfinity, hi = float.PositiveInfinity;
        for (int i = 0; i < v.Length; i++)
        {
            float s = Vector2.Dot(nrm[i], c - v[i]);
            float d = Vector2.Dot(nrm[i], normal);
            if (d > 0f)
            {
                hi = MathF.Min(hi, -s / d);
            }
            else if (d < 0f)
            {
                lo = MathF.Max(lo, -s / d);
            }
            else if (s > 0f)
            {
                lo = float.PositiveInfinity;
                hi = float.NegativeInfinity;
                break;
            }
        }

        lo = MathF.Max(lo, -r);
        hi = MathF.Min(hi, r);
        float t = lo <= hi ? 0.5f * (lo + hi) : Math.Clamp(depth - r, -r, r);
        Vector2 point = c + normal * t;
        return new CollisionDetectionResult(true, new Vector3(normal.X * depth, 0f, normal.Y * depth), new Vector3(normal.X, 0f, normal.Y), new Vector3(point.X, 0f, point.Y));
    }

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
}
