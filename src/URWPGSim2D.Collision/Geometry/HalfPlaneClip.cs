namespace URWPGSim2D.Collision.Geometry;

/// <summary>
/// Sutherland–Hodgman clipping of a convex polygon by one half-plane {p : p·n ≤ offset}.
/// The building block of 8-DOP vertex generation and of contact-region computation.
/// </summary>
internal static class HalfPlaneClip
{
    /// <summary>
    /// Writes the part of <paramref name="input"/> (a convex polygon, any count) with p·n ≤ offset
    /// into <paramref name="output"/> (room for input.Length + 1) and returns its vertex count.
    /// </summary>
    public static int Clip(ReadOnlySpan<Vector2> input, Span<Vector2> output, Vector2 n, float offset)
    {
        int count = 0;
        if (input.IsEmpty)
        {
            return 0;
        }

        Vector2 prev = input[^1];
        float prevDist = Vector2.Dot(prev, n) - offset;
        for (int i = 0; i < input.Length; i++)
        {
            Vector2 cur = input[i];
            float curDist = Vector2.Dot(cur, n) - offset;
            if (curDist <= 0f)
            {
                if (prevDist > 0f)
                {
                    output[count++] = Lerp(prev, cur, prevDist, curDist);
                }

                output[count++] = cur;
            }
            else if (prevDist <= 0f)
            {
                output[count++] = Lerp(prev, cur, prevDist, curDist);
            }

            prev = cur;
            prevDist = curDist;
        }

        return count;
    }

    /// <summary>Drops consecutive vertices closer than <paramref name="tolerance"/> (including last-to-first).</summary>
    public static int RemoveNearDuplicates(Span<Vector2> v, int count, float tolerance)
    {
        float tol2 = tolerance * tolerance;
        int kept = 0;
        for (int i = 0; i < count; i++)
        {
            if (kept == 0 || Vector2.DistanceSquared(v[i], v[kept - 1]) > tol2)
            {
                v[kept++] = v[i];
            }
        }

        while (kept > 1 && Vector2.DistanceSquared(v[kept - 1], v[0]) <= tol2)
        {
            kept--;
        }

        return kept;
    }

    // The point where the edge crosses the line: distances of opposite sign (or one zero).
    private static Vector2 Lerp(Vector2 a, Vector2 b, float da, float db)
    {
        float t = da / (da - db);
        return a + (b - a) * t;
    }
}
