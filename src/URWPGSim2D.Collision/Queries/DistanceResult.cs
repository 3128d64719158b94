namespace URWPGSim2D.Collision.Queries;

/// <summary>
/// How far apart two shapes are (the answer of <see cref="ShapeQuery.Distance(in Shapes.Shape, in Shapes.Shape)"/>):
/// the gap and a closest point on each. Plane vectors, mm (X = world X, Y = world Z), like the shapes.
/// </summary>
public readonly struct DistanceResult
{
    private readonly byte _partA;
    private readonly byte _partB;

    internal DistanceResult(float distance, Vector2 pointA, Vector2 pointB, int partA = -1, int partB = -1)
    {
        Distance = distance;
        PointA = pointA;
        PointB = pointB;
        _partA = (byte)(partA + 1);
        _partB = (byte)(partB + 1);
    }

    /// <summary>The gap between the shapes, mm: 0 when they touch or overlap.</summary>
    public float Distance { get; }

    /// <summary>The point of the first shape nearest the second; when they overlap, a point of the overlap (the narrow phase's action point).</summary>
    public Vector2 PointA { get; }

    /// <summary>The point of the second shape nearest the first; when they overlap, the same point as <see cref="PointA"/>.</summary>
    public Vector2 PointB { get; }

    /// <summary>The first shape's leaf holding <see cref="PointA"/> when it is a fish, else null.</summary>
    public FishPart? PartA => _partA == 0 ? null : (FishPart)(_partA - 1);

    /// <summary>The second shape's leaf holding <see cref="PointB"/> when it is a fish, else null.</summary>
    public FishPart? PartB => _partB == 0 ? null : (FishPart)(_partB - 1);

    /// <summary>The same answer seen with the two shapes swapped.</summary>
    /// <returns>Points and parts exchanged.</returns>
    public DistanceResult Swapped() => new(Distance, PointB, PointA, _partB - 1, _partA - 1);

    /// <inheritdoc />
    public override string ToString() => $"distance {Distance} between ({PointA.X}, {PointA.Y}) and ({PointB.X}, {PointB.Y})";
}
