namespace URWPGSim2D.Collision.Queries;

/// <summary>
/// Where a ray first enters a shape (the answer of <see cref="ShapeQuery.RayCast(in Shapes.Shape, Vector2, Vector2)"/>).
/// Plane vectors, mm (X = world X, Y = world Z).
/// </summary>
public readonly struct RayCastResult
{
    private readonly byte _part;

    internal RayCastResult(Vector2 point, Vector2 normal, float fraction, int part = -1)
    {
        Hit = true;
        Point = point;
        Normal = normal;
        Fraction = fraction;
        _part = (byte)(part + 1);
    }

    /// <summary>The answer for a ray that enters no shape.</summary>
    public static RayCastResult Miss => default;

    /// <summary>Whether the ray enters the shape between its two ends.</summary>
    public bool Hit { get; }

    /// <summary>The entry point, from + <see cref="Fraction"/>·(to − from), mm.</summary>
    public Vector2 Point { get; }

    /// <summary>The shape's outward unit normal at the entry point (facing the ray's start).</summary>
    public Vector2 Normal { get; }

    /// <summary>How far along the ray the entry is: 0 at from, 1 at to.</summary>
    public float Fraction { get; }

    /// <summary>The fish leaf entered when the shape is a fish, else null.</summary>
    public FishPart? Part => _part == 0 ? null : (FishPart)(_part - 1);

    internal int PartIndex => _part - 1;

    /// <inheritdoc />
    public override string ToString() => Hit
        ? $"hit at {Fraction} ({Point.X}, {Point.Y}) normal ({Normal.X}, {Normal.Y})" + (Part is { } p ? $" {p}" : string.Empty)
        : "miss";
}
