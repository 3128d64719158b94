namespace URWPGSim2D.Collision.Geometry;

/// <summary>
/// A borrowed look at any convex "polygon-like" shape: its vertices in counter-clockwise order
/// (positive signed area in x–z coordinates) and the outward unit normal of each edge
/// (edge i runs from vertex i to vertex i+1), which are also the axes a separating-axis test tries.
/// </summary>
/// <remarks>
/// A segment is the two-vertex case (edges A→B and B→A, normals n and −n); a
/// degenerate 8-DOP may even be a single point (no edges, no normals). Views never own memory:
/// they point into a shape or into the caller's stack.
/// </remarks>
internal readonly ref struct ConvexView
{
    public ConvexView(ReadOnlySpan<Vector2> vertices, ReadOnlySpan<Vector2> normals)
    {
        Vertices = vertices;
        Normals = normals;
    }

    /// <summary>Vertices, counter-clockwise, mm.</summary>
    public ReadOnlySpan<Vector2> Vertices { get; }

    /// <summary>Outward unit normal of edge i (vertex i → vertex i+1); empty for a single point.</summary>
    public ReadOnlySpan<Vector2> Normals { get; }

    /// <summary>Projects the vertices, taken relative to <paramref name="origin"/>, on <paramref name="axis"/>.</summary>
    public void Project(Vector2 axis, Vector2 origin, out float min, out float max)
    {
        var v = Vertices;
        float lo = Vector2.Dot(v[0] - origin, axis);
        float hi = lo;
        for (int i = 1; i < v.Length; i++)
        {
            float p = Vector2.Dot(v[i] - origin, axis);
            lo = MathF.Min(lo, p);
            hi = MathF.Max(hi, p);
        }

        min = lo;
        max = hi;
    }

    /// <summary>The vertex farthest along <paramref name="direction"/> (the support point).</summary>
    public Vector2 Support(Vector2 direction)
    {
        var v = Vertices;
        int best = 0;
        float bestDot = Vector2.Dot(v[0], direction);
        for (int i = 1; i < v.Length; i++)
        {
            float d = Vector2.Dot(v[i], direction);
            if (d > bestDot)
            {
                bestDot = d;
                best = i;
            }
        }

        return v[best];
    }
}
