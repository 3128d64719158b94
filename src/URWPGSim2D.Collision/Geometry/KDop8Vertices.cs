using System;
using System.Numerics;
using URWPGSim2D.Collision.Shapes;

namespace URWPGSim2D.Collision.Geometry;

/// <summary>The polygon of an 8-DOP: its slab box clipped by the two diagonal slabs.</summary>
internal static class KDop8Vertices
{
    private static readonly Vector2[] Directions =
    [
        new(1f, 0f), new(KDop8.Diagonal, KDop8.Diagonal), new(0f, 1f), new(-KDop8.Diagonal, KDop8.Diagonal),
        new(-1f, 0f), new(-KDop8.Diagonal, -KDop8.Diagonal), new(0f, -1f), new(KDop8.Diagonal, -KDop8.Diagonal),
    ];

    /// <summary>
    /// Writes the vertices (counter-clockwise, at most 8) of the region min ≤ p·aᵢ ≤ max and
    /// returns their count: 0 when empty, 1 or 2 when it is a point or a segment.
    /// </summary>
    public static int Compute(Vector4 min, Vector4 max, Span<Vector2> destination)
    {
        Span<Vector2> a = stackalloc Vector2[12];
        Span<Vector2> b = stackalloc Vector2[12];
        a[0] = new Vector2(min.X, min.Y);
        a[1] = new Vector2(max.X, min.Y);
        a[2] = new Vector2(max.X, max.Y);
        a[3] = new Vector2(min.X, max.Y);
        int n = 4;
        Vector2 d2 = KDop8.Axis(2), d3 = KDop8.Axis(3);

        // A few ulps of slack on the diagonal slabs: slabs computed from points (a single
        // point, a flat box) must not lose that point to round-off. Callers re-tighten.
        float scale = 1f + MathF.Max(MathF.Max(MathF.Abs(min.X), MathF.Abs(max.X)), MathF.Max(MathF.Abs(min.Y), MathF.Abs(max.Y)));
        float slack = 5e-7f * scale;
        n = HalfPlaneClip.Clip(a[..n], b, d2, max.Z + slack);
        n = HalfPlaneClip.Clip(b[..n], a, -d2, -min.Z + slack);
        n = HalfPlaneClip.Clip(a[..n], b, d3, max.W + slack);
        n = HalfPlaneClip.Clip(b[..n], a, -d3, -min.W + slack);
        n = HalfPlaneClip.RemoveNearDuplicates(a, n, 2f * slack);
        a[..n].CopyTo(destination);
        return n;
    }

    /// <summary>Writes the outward normal of each edge, snapped to the nearest of the eight exact directions.</summary>
    public static void EdgeNormals(ReadOnlySpan<Vector2> vertices, Span<Vector2> normals)
    {
        if (vertices.Length < 2)
        {
            return;
        }

        for (int i = 0; i < vertices.Length; i++)
        {
            Vector2 outward = XZPlane.RightPerp(vertices[(i + 1) % vertices.Length] - vertices[i]);
            Vector2 best = Directions[0];
            float bestDot = Vector2.Dot(outward, best);
            for (int k = 1; k < Directions.Length; k++)
            {
                float d = Vector2.Dot(outward, Directions[k]);
                if (d > bestDot)
                {
                    bestDot = d;
                    best = Directions[k];
                }
            }

            normals[i] = best;
        }
    }
}
