namespace URWPGSim2D.Collision.Shapes;

/// <summary>
/// A convex polygon in the X–Z plane with 3 to <see cref="MaxVertices"/> vertices, mm.
/// Either winding is accepted; the vertices are stored counter-clockwise in x–z coordinates
/// (positive signed area), each with the outward unit normal of the edge that starts there.
/// </summary>
/// <remarks>The vertex and normal arrays are built once, here; queries never allocate.</remarks>
public readonly struct ConvexPolygon
{
    /// <summary>The largest number of vertices a polygon may have.</summary>
    public const int MaxVertices = 64;

    // Relative tolerance for convexity: a vertex may lie this fraction of the polygon's size
    // outside an edge line (round-off of float input) and still count as on it.
    private const float ConvexityTolerance = 1e-5f;

    // Plus this fraction of the largest coordinate: rounding a point near 25,000 mm to float
    // moves it by up to 0.001 mm, whatever the polygon's size.
    private const float CoordinateTolerance = 4.8e-7f;

    private readonly Vector2[]? _vertices;
    private readonly Vector2[]? _normals;

    // Vertices and normals of a polygon of at most eight vertices in vector lanes (PolygonLanes), packed once.
    private readonly float[]? _lanes;

    /// <summary>Creates a convex polygon, validating and normalising its vertices.</summary>
    /// <param name="vertices">3 to <see cref="MaxVertices"/> distinct finite points in either winding, forming a convex polygon of non-zero area.</param>
    /// <exception cref="ArgumentException">Too few or too many vertices, a non-finite coordinate, a repeated vertex, all vertices collinear, or a polygon that is not convex (including self-intersecting outlines).</exception>
    /// <remarks>A vertex may lie outside the line of an edge by 10⁻⁵ of the polygon's size plus 4.8·10⁻⁷ of the largest coordinate (float resolution) and still count as convex.</remarks>
    public ConvexPolygon(ReadOnlySpan<Vector2> vertices)
    {
        const string param = nameof(vertices);
        if (vertices.Length < 3)
        {
            throw new ArgumentException($"polygon needs at least 3 vertices, got {vertices.Length}", param);
        }

        if (vertices.Length > MaxVertices)
        {
            throw new ArgumentException($"polygon has {vertices.Length} vertices, at most {MaxVertices} are allowed", param);
        }

        for (int i = 0; i < vertices.Length; i++)
        {
            Guard.Finite(vertices[i], $"{param}[{i}]");
            for (int j = 0; j < i; j++)
            {
                if (vertices[i] == vertices[j])
                {
                    throw new ArgumentException($"polygon repeats vertex [{vertices[i].X}, {vertices[i].Y}] (indices {j} and {i})", param);
                }
            }
        }

        var v = vertices.ToArray();
        float tolerance = ConvexityTolerance * Size(v) + CoordinateTolerance * MaxAbsCoordinate(v);
        if (AreCollinear(v, tolerance))
        {
            throw new ArgumentException("polygon is degenerate: its vertices are collinear", param);
        }

        // A self-intersecting outline (a bow-tie) has an area near 0 of either sign: whichever
        // way it is turned, the convexity check rejects it.
        if (SignedArea2(v) < 0f)
        {
            Array.Reverse(v);
        }

        if (!IsConvex(v, tolerance))
        {
            throw new ArgumentException("polygon is not convex", param);
        }

        var n = new Vector2[v.Length];
        for (int i = 0; i < v.Length; i++)
        {
            n[i] = Vector2.Normalize(XZPlane.RightPerp(v[(i + 1) % v.Length] - v[i]));
        }

        _vertices = v;
        _normals = n;
        _lanes = PolygonLanes.Fits(v.Length) ? PolygonLanes.Pack(v, n) : null;
        Vector2 c = VertexMean(v);
        float r2 = 0f;
        foreach (var p in v)
        {
            r2 = MathF.Max(r2, Vector2.DistanceSquared(p, c));
        }

        BoundingCircle = Circle.Bounding(c, MathF.Sqrt(r2));
    }

    /// <summary>
    /// A polygon over vertex and normal arrays that are already counter-clockwise, convex and
    /// normalised (a moving body's outline posed in place), without checking or copying them:
    /// the arrays are the caller's and the polygon sees whatever they hold.
    /// </summary>
    internal ConvexPolygon(Vector2[] vertices, Vector2[] normals, in Circle boundingCircle)
    {
        _vertices = vertices;
        _normals = normals;
        _lanes = null;
        BoundingCircle = boundingCircle;
    }

    /// <summary>The vertices, counter-clockwise in x–z coordinates, mm.</summary>
    public ReadOnlySpan<Vector2> Vertices => _vertices;

    /// <summary>The outward unit normal of edge i (from vertex i to vertex i+1).</summary>
    public ReadOnlySpan<Vector2> Normals => _normals;

    /// <summary>The outer bounding circle: centred on the vertex mean, through the farthest vertex.</summary>
    public Circle BoundingCircle { get; }

    /// <summary>This polygon moved by <paramref name="offset"/> mm (allocates a new polygon).</summary>
    /// <param name="offset">Translation in mm.</param>
    /// <returns>The translated polygon.</returns>
    public ConvexPolygon Translated(Vector2 offset)
    {
        Span<Vector2> moved = stackalloc Vector2[Vertices.Length];
        for (int i = 0; i < moved.Length; i++)
        {
            moved[i] = Vertices[i] + offset;
        }

        return new ConvexPolygon(moved);
    }

    /// <summary>The polygon's lanes (<see cref="PolygonLanes.Pack"/>) when it has at most eight vertices, else null.</summary>
    internal float[]? Lanes => _lanes;

    /// <summary>A view of the polygon: its own vertices and edge normals.</summary>
    internal ConvexView View()
    {
        if (_vertices is null)
        {
            throw new InvalidOperationException("the polygon is default(ConvexPolygon) and has no vertices");
        }

        return new ConvexView(_vertices, _normals);
    }

    /// <summary>Twice the signed area (positive for counter-clockwise in x–z coordinates).</summary>
    internal static float SignedArea2(ReadOnlySpan<Vector2> v)
    {
        float a = 0f;
        Vector2 o = v[0];
        for (int i = 1; i + 1 < v.Length; i++)
        {
            a += XZPlane.Cross(v[i] - o, v[i + 1] - o);
        }

        return a;
    }

    private static float Size(ReadOnlySpan<Vector2> v)
    {
        Vector2 lo = v[0], hi = v[0];
        foreach (var p in v)
        {
            lo = Vector2.Min(lo, p);
            hi = Vector2.Max(hi, p);
        }

        return MathF.Max(hi.X - lo.X, hi.Y - lo.Y);
    }

    private static float MaxAbsCoordinate(ReadOnlySpan<Vector2> v)
    {
        float m = 0f;
        foreach (var p in v)
        {
            m = MathF.Max(m, MathF.Max(MathF.Abs(p.X), MathF.Abs(p.Y)));
        }

        return m;
    }

    // Every vertex within `tolerance` of the line through two vertices that are farthest apart
    // (p: farthest from v[0]; q: farthest from p).
    private static bool AreCollinear(ReadOnlySpan<Vector2> v, float tolerance)
    {
        Vector2 p = Farthest(v, v[0]);
        Vector2 q = Farthest(v, p);
        Vector2 d = q - p;
        float len = d.Length();
        foreach (var r in v)
        {
            if (MathF.Abs(XZPlane.Cross(d, r - p)) > tolerance * len)
            {
                return false;
            }
        }

        return true;
    }

    private static Vector2 Farthest(ReadOnlySpan<Vector2> v, Vector2 from)
    {
        Vector2 best = from;
        float bestD = -1f;
        foreach (var p in v)
        {
            float d = Vector2.DistanceSquared(p, from);
            if (d > bestD)
            {
                bestD = d;
                best = p;
            }
        }

        return best;
    }

    private static Vector2 VertexMean(ReadOnlySpan<Vector2> v)
    {
        Vector2 s = Vector2.Zero;
        foreach (var p in v)
        {
            s += p - v[0];
        }

        return v[0] + s / v.Length;
    }

    // Convex and simple: every vertex lies on the inner side of every edge line (within tolerance).
    private static bool IsConvex(ReadOnlySpan<Vector2> v, float tolerance)
    {
        for (int i = 0; i < v.Length; i++)
        {
            Vector2 a = v[i];
            Vector2 edge = v[(i + 1) % v.Length] - a;
            float len = edge.Length();
            for (int j = 0; j < v.Length; j++)
            {
                if (XZPlane.Cross(edge, v[j] - a) < -tolerance * len)
                {
                    return false;
                }
            }
        }

        return true;
    }
}
