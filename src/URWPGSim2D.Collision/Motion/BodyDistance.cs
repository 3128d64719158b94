using URWPGSim2D.Collision.Motion;

namespace URWPGSim2D.Collision.Queries;

/// <summary>The body of a <see cref="MotionWorld"/> or a <see cref="QueryWorld"/> nearest a point, and how near.</summary>
public readonly struct BodyDistance
{
    internal BodyDistance(BodyId id, in DistanceResult result)
    {
        Id = id;
        Result = result;
    }

    /// <summary>The nearest body (its index in the world, <see cref="BodyId.Index"/> of <see cref="Id"/>), or −1 when the world is empty.</summary>
    public int Body => Id.Index;

    /// <summary>The nearest body: its id in the motion world (for a <see cref="QueryWorld"/>, the one it keeps its bodies in), or <c>default</c> when the world is empty.</summary>
    public BodyId Id { get; }

    /// <summary>The distance from the body (<see cref="DistanceResult.PointA"/>) to the point (<see cref="DistanceResult.PointB"/>).</summary>
    public DistanceResult Result { get; }

    /// <inheritdoc />
    public override string ToString() => Body < 0 ? "none" : $"body {Body}: {Result}";
}
