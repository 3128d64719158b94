namespace URWPGSim2D.Collision.Queries;

/// <summary>
/// When a shape moved along a translation first touches another (the answer of
/// <see cref="ShapeQuery.Cast(in Shapes.Shape, Vector2, in Shapes.Shape)"/>). Plane vectors, mm.
/// </summary>
public readonly struct ShapeCastResult
{
    private readonly byte _partA;
    private readonly byte _partB;

    internal ShapeCastResult(float fraction, Vector2 point, Vector2 normal, int partA = -1, int partB = -1)
    {
        Hit = true;
        Fraction = fraction;
        Point = point;
        Normal = normal;
        _partA = (byte)(partA + 1);
        _partB = (byte)(partB + 1);
    }

    /// <summary>The answer for a translation along which the shapes never touch.</summary>
    public static ShapeCastResult Miss => default;

    /// <summary>Whether the moving shape touches the other before the end of the translation.</summary>
    public bool Hit { get; }

    /// <summary>The part of the translation done at the first contact: 0 (already touching or overlapping) to 1.</summary>
    public float Fraction { get; }

    /// <summary>The contact point, on the other shape's boundary (the action point when they overlap from the start), mm.</summary>
    public Vector2 Point { get; }

    /// <summary>The unit normal of the contact, from the other shape toward the moving one.</summary>
    public Vector2 Normal { get; }

    /// <summary>The moving shape's leaf in contact when it is a fish, else null.</summary>
    public FishPart? PartA => _partA == 0 ? null : (FishPart)(_partA - 1);

    /// <summary>The other shape's leaf in contact when it is a fish, else null.</summary>
    public FishPart? PartB => _partB == 0 ? null : (FishPart)(_partB - 1);

    internal ShapeCastResult WithParts(int partA, int partB) => Hit ? new(Fraction, Point, Normal, partA, partB) : this;

    /// <inheritdoc />
    public override string ToString() => Hit
        ? $"hit at {Fraction} ({Point.X}, {Point.Y}) normal ({Normal.X}, {Normal.Y})"
        : "miss";
}
