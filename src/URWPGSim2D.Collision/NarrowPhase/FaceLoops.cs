using System.Runtime.InteropServices;

namespace URWPGSim2D.Collision.NarrowPhase;

/// <summary>
/// The loops over a convex shape's faces (outward unit normal nᵢ through vertex vᵢ) that the
/// pair tests spend their time in: the separating-axis test's separations sᵢ = min over the other
/// shape's vertices w of nᵢ·w − nᵢ·vᵢ and their greatest, a point's farthest face line (circle
/// against polygon), whether a point is inside, the face most anti-parallel to a direction, and
/// where a line enters and leaves the shape.
/// </summary>
/// <remarks>
/// With vector hardware four faces share a 128-bit vector (their normals and vertices are
/// gathered into x and z lanes) and each of the other shape's vertices is broadcast against
/// them: four dot products per two multiplications and one addition. Every lane does the same
/// roundings as <see cref="Vector2.Dot"/> in the scalar loop, and ties go to the lowest face
/// index in both, so the two paths agree bit for bit. The loops are never inlined: inlined
/// into a caller that inlines the rest of a pair test, they exhaust the JIT's inlining budget and
/// leave small helpers (vector constructors) as calls.
/// </remarks>
internal static class FaceLoops
{
    /// <summary>
    /// The greatest separation of <paramref name="other"/> from the faces of
    /// <paramref name="reference"/> (the first face wins a tie); false as soon as some face has
    /// sᵢ ≥ 0 (apart or touching). A reference with no faces (a single point): face −1,
    /// separation −∞.
    /// </summary>
    public static bool GreatestSeparation(ReadOnlySpan<Vector2> reference, ReadOnlySpan<Vector2> normals, ReadOnlySpan<Vector2> other, out int face, out float separation, bool vector = true) =>
        vector && Vector128.IsHardwareAccelerated
            ? GreatestSeparationVector(reference, normals, other, out face, out separation)
            : GreatestSeparationScalar(reference, normals, other, out face, out separation);

    /// <summary>The same answer one face at a time (no vector hardware).</summary>
    internal static bool GreatestSeparationScalar(ReadOnlySpan<Vector2> reference, ReadOnlySpan<Vector2> normals, ReadOnlySpan<Vector2> other, out int face, out float separation)
    {
        face = -1;
        separation = float.NegativeInfinity;
        for (int i = 0; i < normals.Length; i++)
        {
            Vector2 n = normals[i];
            float lowest = float.PositiveInfinity;
            foreach (Vector2 w in other)
            {
                float d = Vector2.Dot(n, w);
                lowest = d < lowest ? d : lowest;
            }

            float s = lowest - Vector2.Dot(n, reference[i]);
            if (s >= 0f)
            {
                return false;
            }

            if (s > separation)
            {
                separation = s;
                face = i;
            }
        }

        return true;
    }

    /// <summary>The same answer four faces at a time.</summary>
    [MethodImpl(MethodImplOptions.NoInlining)]
    internal static bool GreatestSeparationVector(ReadOnlySpan<Vector2> reference, ReadOnlySpan<Vector2> normals, ReadOnlySpan<Vector2> other, out int face, out float separation)
    {
        face = -1;
        separation = float.NegativeInfinity;
        int count = normals.Length;
        ref Vector2 w0 = ref MemoryMarshal.GetReference(other);
        for (int start = 0; start < count; start += 4)
        {
            // The last group of a shape with four or more faces overlaps the one before it; a
            // smaller shape repeats its last face. A repeated face never wins (ties go to the first).
            int at = count >= 4 ? Math.Min(start, count - 4) : 0;
            Lanes(normals, at, out var nx, out var nz);
            Lanes(reference, at, out var vx, out var vz);
            var offset = (nx * vx) + (nz * vz);
            var lowest = Vector128.Create(float.PositiveInfinity);
            for (int j = 0; j < other.Length; j++)
            {
                Vector2 w = Unsafe.Add(ref w0, j);
                lowest = Vector128.MinNative(lowest, (nx * Vector128.Create(w.X)) + (nz * Vector128.Create(w.Y)));
            }

            var s = lowest - offset;
            if (Vector128.GreaterThanOrEqualAny(s, Vector128<float>.Zero))
            {
                return false;
            }

            var best = Vector128.MaxNative(s, Vector128.Shuffle(s, Vector128.Create(2, 3, 0, 1)));
            best = Vector128.MaxNative(best, Vector128.Shuffle(best, Vector128.Create(1, 0, 3, 2)));
            float groupBest = best.ToScalar();
            if (groupBest > separation)
            {
                separation = groupBest;
                int lane = BitOperations.TrailingZeroCount(Vector128.Equals(s, best).ExtractMostSignificantBits());
                face = Math.Min(at + lane, count - 1);
            }
        }

        return true;
    }

    /// <summary>
    /// The face whose line <paramref name="p"/> lies farthest outside, sᵢ = nᵢ·(p − vᵢ) (the
    /// first face wins a tie); false as soon as some sᵢ ≥ <paramref name="limit"/>. Four faces
    /// at a time where the hardware allows and <paramref name="vector"/> is set, with
    /// <see cref="Vector2.Dot"/>'s roundings; else one at a time.
    /// </summary>
    [MethodImpl(MethodImplOptions.NoInlining)]
    public static bool Farthest(ReadOnlySpan<Vector2> vertices, ReadOnlySpan<Vector2> normals, Vector2 p, float limit, out int face, out float distance, bool vector = true)
    {
        int count = normals.Length;
        face = 0;
        distance = float.NegativeInfinity;
        if (!vector || !Vector128.IsHardwareAccelerated)
        {
            for (int i = 0; i < count; i++)
            {
                float s = Vector2.Dot(normals[i], p - vertices[i]);
                if (s >= limit)
                {
                    return false;
                }

                if (s > distance)
                {
                    distance = s;
                    face = i;
                }
            }

            return true;
        }

        var px = Vector128.Create(p.X);
        var pz = Vector128.Create(p.Y);
        var bound = Vector128.Create(limit);
        for (int start = 0; start < count; start += 4)
        {
            int at = count >= 4 ? Math.Min(start, count - 4) : 0;
            Lanes(normals, at, out var nx, out var nz);
            Lanes(vertices, at, out var vx, out var vz);
            var s = (nx * (px - vx)) + (nz * (pz - vz));
            if (Vector128.GreaterThanOrEqualAny(s, bound))
            {
                return false;
            }

            var best = Vector128.MaxNative(s, Vector128.Shuffle(s, Vector128.Create(2, 3, 0, 1)));
            best = Vector128.MaxNative(best, Vector128.Shuffle(best, Vector128.Create(1, 0, 3, 2)));
            float groupBest = best.ToScalar();
            if (groupBest > distance)
            {
                distance = groupBest;
                face = Math.Min(at + BitOperations.TrailingZeroCount(Vector128.Equals(s, best).ExtractMostSignificantBits()), count - 1);
            }
        }

        return true;
    }

    /// <summary>
    /// Whether n·(p − v) ≤ <paramref name="tolerance"/> for every face (normal n through vertex
    /// v, relative coordinates): p inside the convex shape, or within the tolerance of it.
    /// Four faces at a time where the hardware allows and <paramref name="vector"/> is set, with
    /// <see cref="Vector2.Dot"/>'s roundings; else one at a time.
    /// </summary>
    [MethodImpl(MethodImplOptions.NoInlining)]
    public static bool Inside(ReadOnlySpan<Vector2> vertices, ReadOnlySpan<Vector2> normals, Vector2 p, float tolerance, bool vector = true)
    {
        int count = normals.Length;
        if (!vector || !Vector128.IsHardwareAccelerated)
        {
            for (int i = 0; i < count; i++)
            {
                if (Vector2.Dot(normals[i], p - vertices[i]) > tolerance)
                {
                    return false;
                }
            }

            return true;
        }

        var px = Vector128.Create(p.X);
        var pz = Vector128.Create(p.Y);
        var limit = Vector128.Create(tolerance);
        for (int start = 0; start < count; start += 4)
        {
            int at = count >= 4 ? Math.Min(start, count - 4) : 0;
            Lanes(normals, at, out var nx, out var nz);
            Lanes(vertices, at, out var vx, out var vz);
            if (Vector128.GreaterThanAny((nx * (px - vx)) + (nz * (pz - vz)), limit))
            {
                return false;
            }
        }

        return true;
    }

    /// <summary>
    /// The index of the direction with the least dot product with <paramref name="d"/> (the first
    /// one on a tie; at least one direction): e.g. the edge most anti-parallel to a face. Four at a
    /// time where the hardware allows and <paramref name="vector"/> is set, else one at a time.
    /// </summary>
    [MethodImpl(MethodImplOptions.NoInlining)]
    public static int LeastDot(ReadOnlySpan<Vector2> directions, Vector2 d, bool vector = true)
    {
        int count = directions.Length, index = 0;
        float least = float.PositiveInfinity;
        if (!vector || !Vector128.IsHardwareAccelerated)
        {
            for (int j = 0; j < count; j++)
            {
                float dot = Vector2.Dot(directions[j], d);
                if (dot < least)
                {
                    least = dot;
                    index = j;
                }
            }

            return index;
        }

        var dx = Vector128.Create(d.X);
        var dz = Vector128.Create(d.Y);
        for (int start = 0; start < count; start += 4)
        {
            int at = count >= 4 ? Math.Min(start, count - 4) : 0;
            Lanes(directions, at, out var x, out var z);
            var dots = (x * dx) + (z * dz);
            var low = Vector128.MinNative(dots, Vector128.Shuffle(dots, Vector128.Create(2, 3, 0, 1)));
            low = Vector128.MinNative(low, Vector128.Shuffle(low, Vector128.Create(1, 0, 3, 2)));
            float groupLeast = low.ToScalar();
            if (groupLeast < least)
            {
                least = groupLeast;
                index = Math.Min(at + BitOperations.TrailingZeroCount(Vector128.Equals(dots, low).ExtractMostSignificantBits()), count - 1);
            }
        }

        return index;
    }

    /// <summary>
    /// The interval [lo, hi] of t for which p + t·u lies in the convex polygon (at least three
    /// vertices; empty: lo &gt; hi), four faces at a time: for each face, s = n·(p − v) and
    /// d = n·u bound t by −s/d from above (d &gt; 0) or below (d &lt; 0); a face parallel to u with
    /// p outside it (d = 0, s &gt; 0) empties it. The roundings are those of the scalar loop in
    /// <see cref="ContactRegion.LineInterval"/>.
    /// </summary>
    [MethodImpl(MethodImplOptions.NoInlining)]
    public static void LineInterval(ReadOnlySpan<Vector2> vertices, ReadOnlySpan<Vector2> normals, Vector2 p, Vector2 u, out float lo, out float hi)
    {
        int count = normals.Length;
        var px = Vector128.Create(p.X);
        var pz = Vector128.Create(p.Y);
        var ux = Vector128.Create(u.X);
        var uz = Vector128.Create(u.Y);
        var low = Vector128.Create(float.NegativeInfinity);
        var high = Vector128.Create(float.PositiveInfinity);
        for (int start = 0; start < count; start += 4)
        {
            int at = count >= 4 ? Math.Min(start, count - 4) : 0;
            Lanes(normals, at, out var nx, out var nz);
            Lanes(vertices, at, out var vx, out var vz);
            var s = (nx * (px - vx)) + (nz * (pz - vz));
            var d = (nx * ux) + (nz * uz);
            var zero = Vector128<float>.Zero;
            if (Vector128.EqualsAny(d, zero) && Vector128.GreaterThanAny(Vector128.ConditionalSelect(Vector128.Equals(d, zero), s, zero), zero))
            {
                lo = float.PositiveInfinity;
                hi = float.NegativeInfinity;
                return;
            }

            var t = -s / d;
            high = Vector128.MinNative(high, Vector128.ConditionalSelect(Vector128.GreaterThan(d, zero), t, Vector128.Create(float.PositiveInfinity)));
            low = Vector128.MaxNative(low, Vector128.ConditionalSelect(Vector128.LessThan(d, zero), t, Vector128.Create(float.NegativeInfinity)));
        }

        high = Vector128.MinNative(high, Vector128.Shuffle(high, Vector128.Create(2, 3, 0, 1)));
        low = Vector128.MaxNative(low, Vector128.Shuffle(low, Vector128.Create(2, 3, 0, 1)));
        hi = ExactMinMax.Min(high.ToScalar(), high.GetElement(1));
        lo = ExactMinMax.Max(low.ToScalar(), low.GetElement(1));
    }

    // The x and z coordinates of points at, at+1, at+2, at+3 in four lanes each (a span shorter
    // than four repeats its last point).
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    private static void Lanes(ReadOnlySpan<Vector2> points, int at, out Vector128<float> x, out Vector128<float> z)
    {
        if (points.Length - at >= 4)
        {
            ref float first = ref Unsafe.As<Vector2, float>(ref MemoryMarshal.GetReference(points));
            if (Vector256.IsHardwareAccelerated)
            {
                var four = Vector256.Shuffle(Vector256.LoadUnsafe(ref first, (nuint)(2 * at)), Vector256.Create(0, 2, 4, 6, 1, 3, 5, 7));
                x = four.GetLower();
                z = four.GetUpper();
                return;
            }

            var low = Vector128.LoadUnsafe(ref first, (nuint)(2 * at));
            var high = Vector128.LoadUnsafe(ref first, (nuint)((2 * at) + 4));
            x = Vector128.Create(low.GetElement(0), low.GetElement(2), high.GetElement(0), high.GetElement(2));
            z = Vector128.Create(low.GetElement(1), low.GetElement(3), high.GetElement(1), high.GetElement(3));
            return;
        }

        int last = points.Length - 1;
        Vector2 p0 = points[Math.Min(at, last)], p1 = points[Math.Min(at + 1, last)];
        Vector2 p2 = points[Math.Min(at + 2, last)], p3 = points[last];
        x = Vector128.Create(p0.X, p1.X, p2.X, p3.X);
        z = Vector128.Create(p0.Y, p1.Y, p2.Y, p3.Y);
    }
}
