namespace URWPGSim2D.Collision.Queries;

/// <summary>
/// The distance between the cores of two convex shapes by the Gilbert–Johnson–Keerthi descent
/// over the Minkowski difference A − B: a simplex of at most three support points, reduced each
/// step to the feature (point or edge) nearest the origin. On polygons it ends, in at most
/// <see cref="MaxIterations"/> steps, when a support pair repeats: the simplex then holds the
/// closest features, so the result is that of the exact vertex–edge distance up to float round-off.
/// All arithmetic is relative to A's first vertex, so shapes far from the origin keep their precision.
/// </summary>
internal static class Gjk
{
    /// <summary>More than any pair of polygons of at most 64 vertices needs; a guard against cycling in round-off.</summary>
    public const int MaxIterations = 40;

    /// <summary>
    /// The distance between the core of <paramref name="a"/> moved by <paramref name="offsetA"/>
    /// and the core of <paramref name="b"/>, with the closest points (world, A's point already moved).
    /// 0 when the cores overlap or touch (the points are then a common point, approximately).
    /// <paramref name="separation"/> is pointA − pointB computed in the local frame (precise even
    /// when the gap is far below the float step of the world coordinates).
    /// </summary>
    public static float Distance(scoped in QueryShape a, Vector2 offsetA, scoped in QueryShape b, out Vector2 pointA, out Vector2 pointB, out Vector2 separation)
    {
        var va = a.Vertices;
        var vb = b.Vertices;
        Vector2 origin = va[0];

        // B relative to A's first vertex, then moved against A's offset (difference of near values first).
        Vector2 shift = -offsetA;
        Simplex s = default;
        s.V1 = Vertex(va, vb, 0, 0, origin, shift);
        s.Count = 1;
        s.L1 = 1f;

        for (int iteration = 0; iteration < MaxIterations; iteration++)
        {
            // The support pairs before the reduction: one dropped by it may come back (a collinear
            // support point on a box's edge); meeting any of them again means no progress.
            int savedA1 = s.V1.IndexA, savedB1 = s.V1.IndexB, savedA2 = s.V2.IndexA, savedB2 = s.V2.IndexB;
            int savedA3 = s.V3.IndexA, savedB3 = s.V3.IndexB, saved = s.Count;
            if (s.Count == 2)
            {
                s.Solve2();
            }
            else if (s.Count == 3)
            {
                s.Solve3();
            }

            if (s.Count == 3)
            {
                break; // the origin is inside the triangle: the cores overlap
            }

            Vector2 closest = s.Closest();

            if (XZPlane.Dot(closest, closest) <= 1e-12f)
            {
                break; // touching (or overlapping on the simplex)
            }

            // Toward the origin: from a point, straight at it; from an edge, along the edge's
            // normal (exactly perpendicular, however the closest point rounded).
            Vector2 direction = s.Count == 1 ? -closest : TowardOrigin(s.V1.W, s.V2.W);
            int ia = a.Support(direction);
            int ib = b.Support(-direction);
            if ((ia == savedA1 && ib == savedB1) || (saved > 1 && ia == savedA2 && ib == savedB2) || (saved > 2 && ia == savedA3 && ib == savedB3))
            {
                break; // no new support point: converged
            }

            var w = Vertex(va, vb, ia, ib, origin, shift);

            // No progress toward the origin beyond round-off: the simplex is the closest feature.
            float reached = XZPlane.Dot(direction, s.V1.W);
            if (XZPlane.Dot(direction, w.W) - reached <= 1e-6f * MathF.Abs(reached))
            {
                break;
            }

            if (s.Count == 1)
            {
                s.V2 = w;
            }
            else
            {
                s.V3 = w;
            }

            s.Count++;
        }

        s.Points(out Vector2 pa, out Vector2 pb);
        Vector2 frame = origin + offsetA;
        pointA = frame + pa;
        pointB = frame + pb;
        separation = s.Count == 3 ? Vector2.Zero : pa - pb;
        return separation.Length();
    }

    // The normal of edge w1w2 on the origin's side (not normalised).
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    private static Vector2 TowardOrigin(Vector2 w1, Vector2 w2)
    {
        Vector2 e = w2 - w1;
        Vector2 left = new(-e.Y, e.X);
        return XZPlane.Cross(e, -w1) > 0f ? left : -left;
    }

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    private static SimplexVertex Vertex(ReadOnlySpan<Vector2> va, ReadOnlySpan<Vector2> vb, int ia, int ib, Vector2 origin, Vector2 shift)
    {
        Vector2 a = va[ia] - origin;
        Vector2 b = (vb[ib] - origin) + shift;
        return new SimplexVertex { A = a, B = b, W = a - b, IndexA = ia, IndexB = ib };
    }

    private struct SimplexVertex
    {
        public Vector2 A;
        public Vector2 B;
        public Vector2 W;
        public int IndexA;
        public int IndexB;
    }

    private struct Simplex
    {
        public SimplexVertex V1;
        public SimplexVertex V2;
        public SimplexVertex V3;
        public float L1;
        public float L2;
        public float L3;
        public int Count;

        public readonly Vector2 Closest() => Count switch
        {
            1 => V1.W,
            2 => (L1 * V1.W) + (L2 * V2.W),
            _ => Vector2.Zero,
        };

        public readonly void Points(out Vector2 a, out Vector2 b)
        {
            switch (Count)
            {
                case 1:
                    a = V1.A;
                    b = V1.B;
                    break;
                case 2:
                    a = (L1 * V1.A) + (L2 * V2.A);
                    b = (L1 * V1.B) + (L2 * V2.B);
                    break;
                default:
                    a = (L1 * V1.A) + (L2 * V2.A) + (L3 * V3.A);
                    b = a;
                    break;
            }
        }

        // The closest point of segment V1V2 to the origin, as barycentric weights.
        public void Solve2()
        {
            Vector2 w1 = V1.W, w2 = V2.W;
            Vector2 e = w2 - w1;
            float toward2 = -XZPlane.Dot(w1, e);
            if (toward2 <= 0f)
            {
                L1 = 1f;
                Count = 1;
                return;
            }

            float toward1 = XZPlane.Dot(w2, e);
            if (toward1 <= 0f)
            {
                V1 = V2;
                L1 = 1f;
                Count = 1;
                return;
            }

            float inv = 1f / (toward1 + toward2);
            L1 = toward1 * inv;
            L2 = toward2 * inv;
        }

        // The closest feature of triangle V1V2V3 to the origin (a vertex, an edge, or the inside).
        public void Solve3()
        {
            Vector2 w1 = V1.W, w2 = V2.W, w3 = V3.W;

            Vector2 e12 = w2 - w1;
            float e12To1 = XZPlane.Dot(w2, e12);
            float e12To2 = -XZPlane.Dot(w1, e12);

            Vector2 e13 = w3 - w1;
            float e13To1 = XZPlane.Dot(w3, e13);
            float e13To3 = -XZPlane.Dot(w1, e13);

            Vector2 e23 = w3 - w2;
            float e23To2 = XZPlane.Dot(w3, e23);
            float e23To3 = -XZPlane.Dot(w2, e23);

            float area = XZPlane.Cross(e12, e13);
            float u123 = area * XZPlane.Cross(w2, w3);
            float v123 = area * XZPlane.Cross(w3, w1);
            float w123 = area * XZPlane.Cross(w1, w2);

            if (e12To2 <= 0f && e13To3 <= 0f)
            {
                L1 = 1f;
                Count = 1;
                return;
            }

            if (e12To1 > 0f && e12To2 > 0f && w123 <= 0f)
            {
                float inv = 1f / (e12To1 + e12To2);
                L1 = e12To1 * inv;
                L2 = e12To2 * inv;
                Count = 2;
                return;
            }

            if (e13To1 > 0f && e13To3 > 0f && v123 <= 0f)
            {
                float inv = 1f / (e13To1 + e13To3);
                L1 = e13To1 * inv;
                L2 = e13To3 * inv;
                V2 = V3;
                Count = 2;
                return;
            }

            if (e12To1 <= 0f && e23To3 <= 0f)
            {
                V1 = V2;
                L1 = 1f;
                Count = 1;
                return;
            }

            if (e13To1 <= 0f && e23To2 <= 0f)
            {
                V1 = V3;
                L1 = 1f;
                Count = 1;
                return;
            }

            if (e23To2 > 0f && e23To3 > 0f && u123 <= 0f)
            {
                float inv = 1f / (e23To2 + e23To3);
                L2 = e23To3 * inv;
                L1 = e23To2 * inv;
                V1 = V2;
                V2 = V3;
                Count = 2;
                return;
            }

            float invArea = 1f / (u123 + v123 + w123);
            L1 = u123 * invArea;
            L2 = v123 * invArea;
            L3 = w123 * invArea;
        }
    }
}
