namespace URWPGSim2D.Collision.Queries;

/// <summary>
/// A convex shape as the queries see it: a core (1 to <see cref="ConvexPolygon.MaxVertices"/>
/// vertices, counter-clockwise, with the outward normal of each edge when there are at least
/// three) swept by a disc of <see cref="Radius"/>. A circle is one vertex and its radius; a
/// segment two vertices; boxes, 8-DOPs, polygons and fish leaves their outline and radius 0.
/// </summary>
internal readonly ref struct QueryShape
{
    public QueryShape(ReadOnlySpan<Vector2> vertices, ReadOnlySpan<Vector2> normals, float radius)
    {
        Vertices = vertices;
        Normals = normals;
        Radius = radius;
    }

    /// <summary>The core's vertices, mm.</summary>
    public ReadOnlySpan<Vector2> Vertices { get; }

    /// <summary>Outward unit normal of edge i (vertex i → i+1) when the core has three vertices or more; else empty.</summary>
    public ReadOnlySpan<Vector2> Normals { get; }

    /// <summary>The radius swept around the core, mm (0 but for circles).</summary>
    public float Radius { get; }

    /// <summary>The shape held by <paramref name="shape"/>; boxes and segments are written into <paramref name="buffer"/>.</summary>
    public static QueryShape Of(in Shape shape, ref VertexBuffer8 buffer) => shape.Kind switch
    {
        ShapeKind.Circle => Of(shape.CircleRef, ref buffer),
        ShapeKind.Aabb => Of(shape.AabbRef, ref buffer),
        ShapeKind.KDop8 => Of(shape.KDop8Ref),
        ShapeKind.Polygon => Of(shape.PolygonRef),
        _ => Of(shape.SegmentRef, ref buffer),
    };

    /// <summary>A circle: its centre, written into <paramref name="buffer"/>, and its radius.</summary>
    public static QueryShape Of(in Circle circle, ref VertexBuffer8 buffer)
    {
        buffer[0] = circle.Center;
        return new QueryShape(((ReadOnlySpan<Vector2>)buffer)[..1], default, circle.Radius);
    }

    /// <summary>A box: its four corners (written into the first half of <paramref name="buffer"/>) and their normals.</summary>
    public static QueryShape Of(in Aabb box, ref VertexBuffer8 buffer)
    {
        Span<Vector2> corners = buffer;
        box.WriteVertices(corners);
        var view = Aabb.View(corners[..4]);
        return new QueryShape(view.Vertices, view.Normals, 0f);
    }

    /// <summary>An 8-DOP: its own vertices (1 to 8).</summary>
    public static QueryShape Of(in KDop8 kdop)
    {
        var view = kdop.View();
        return new QueryShape(view.Vertices, view.Vertices.Length >= 3 ? view.Normals : default, 0f);
    }

    /// <summary>A polygon: its own vertices and normals.</summary>
    public static QueryShape Of(in ConvexPolygon polygon)
    {
        var view = polygon.View();
        return new QueryShape(view.Vertices, view.Normals, 0f);
    }

    /// <summary>A segment: its two ends, written into <paramref name="buffer"/>.</summary>
    public static QueryShape Of(in Segment segment, ref VertexBuffer8 buffer)
    {
        buffer[0] = segment.A;
        buffer[1] = segment.B;
        return new QueryShape(((ReadOnlySpan<Vector2>)buffer)[..2], default, 0f);
    }

    /// <summary>A single point (radius 0).</summary>
    public static QueryShape Point(ref VertexBuffer8 buffer, Vector2 point)
    {
        buffer[0] = point;
        return new QueryShape(((ReadOnlySpan<Vector2>)buffer)[..1], default, 0f);
    }

    /// <summary>A fish leaf or any convex outline with its normals.</summary>
    public static QueryShape Of(ConvexView view) => new(view.Vertices, view.Normals, 0f);

    /// <summary>The index of the vertex farthest along <paramref name="direction"/> (the first of equals).</summary>
    public int Support(Vector2 direction)
    {
        var v = Vertices;
        int best = 0;
        float bestDot = XZPlane.Dot(v[0], direction);
        for (int i = 1; i < v.Length; i++)
        {
            float d = XZPlane.Dot(v[i], direction);
            if (d > bestDot)
            {
                bestDot = d;
                best = i;
            }
        }

        return best;
    }
}
