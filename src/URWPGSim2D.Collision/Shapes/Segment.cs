namespace URWPGSim2D.Collision.Shapes;

/// <summary>A line segment between two distinct points of the X–Z plane, mm (a wall, a thin edge, a ray of motion).</summary>
public readonly struct Segment
{
    /// <summary>Creates a segment, validating its end points.</summary>
    /// <param name="a">First end point, mm.</param>
    /// <param name="b">Second end point, mm; must differ from <paramref name="a"/>.</param>
    /// <exception cref="ArgumentException">A coordinate is not finite, or the two points coincide.</exception>
    public Segment(Vector2 a, Vector2 b)
    {
        Guard.Finite(a, nameof(a));
        Guard.Finite(b, nameof(b));
        if (a == b)
        {
            throw new ArgumentException($"segment has zero length: both ends are [{a.X}, {a.Y}]", nameof(b));
        }

        A = a;
        B = b;
    }

    /// <summary>First end point, mm.</summary>
    public Vector2 A { get; }

    /// <summary>Second end point, mm.</summary>
    public Vector2 B { get; }

    /// <summary>The outer bounding circle: centred at the midpoint, through both ends.</summary>
    public Circle BoundingCircle => Circle.Bounding((A + B) * 0.5f, (B - A).Length() * 0.5f);

    /// <summary>This segment moved by <paramref name="offset"/> mm.</summary>
    /// <param name="offset">Translation in mm.</param>
    /// <returns>The translated segment.</returns>
    public Segment Translated(Vector2 offset) => new(A + offset, B + offset);

    /// <summary>Writes the view data: the two ends and the normals of A→B and B→A.</summary>
    internal void WriteView(Span<Vector2> vertices, Span<Vector2> normals)
    {
        vertices[0] = A;
        vertices[1] = B;
        Vector2 n = Vector2.Normalize(XZPlane.RightPerp(B - A));
        normals[0] = n;
        normals[1] = -n;
    }

    /// <summary>A view over data written by <see cref="WriteView"/>.</summary>
    internal static ConvexView View(ReadOnlySpan<Vector2> vertices, ReadOnlySpan<Vector2> normals) =>
        new(vertices, normals);
}
