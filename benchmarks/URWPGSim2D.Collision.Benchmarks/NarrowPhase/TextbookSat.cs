namespace URWPGSim2D.Collision.Benchmarks.NarrowPhase;

/// <summary>
/// Baseline: the separating-axis test as a textbook (and the original simulator's style) writes
/// it — a list of axes built per call, vertex arrays projected one axis at a time, no contact
/// region. Box2D.NET and Aether.Physics2D are not served by this machine's package registry, so
/// this and circle–circle are the in-run baselines.
/// </summary>
internal static class TextbookSat
{
    public static bool Test(Vector2[] a, Vector2[] b, out Vector2 mtv)
    {
        var axes = new List<Vector2>(a.Length + b.Length);
        AddEdgeNormals(a, axes);
        AddEdgeNormals(b, axes);
        float best = float.MaxValue;
        mtv = Vector2.Zero;
        foreach (var axis in axes)
        {
            float[] pa = Project(a, axis);
            float[] pb = Project(b, axis);
            float overlap = MathF.Min(pa[1], pb[1]) - MathF.Max(pa[0], pb[0]);
            if (overlap <= 0f)
            {
                mtv = Vector2.Zero;
                return false;
            }

            if (overlap < best)
            {
                best = overlap;
                float sign = (pa[0] + pa[1]) < (pb[0] + pb[1]) ? -1f : 1f;
                mtv = axis * (overlap * sign);
            }
        }

        return true;
    }

    private static void AddEdgeNormals(Vector2[] polygon, List<Vector2> axes)
    {
        for (int i = 0; i < polygon.Length; i++)
        {
            Vector2 e = polygon[(i + 1) % polygon.Length] - polygon[i];
            axes.Add(Vector2.Normalize(new Vector2(e.Y, -e.X)));
        }
    }

    private static float[] Project(Vector2[] polygon, Vector2 axis)
    {
        float min = float.MaxValue, max = float.MinValue;
        foreach (var p in polygon)
        {
            float d = Vector2.Dot(p, axis);
            min = MathF.Min(min, d);
            max = MathF.Max(max, d);
        }

        return [min, max];
    }
}
