namespace URWPGSim2D.Collision.Queries;

/// <summary>The body of a <see cref="QueryWorld"/> nearest a point, and how near.</summary>
public readonly struct BodyDistance
{
    internal BodyDistance(int body, in DistanceResult result)
    {
        Body = body;
        Result = result;
    }

    /// <summary>The nearest body (its index in the world), or −1 when the world is empty.</summary>
    public int Body { get; }

    /// <summary>The distance from the body (<see cref="DistanceResult.PointA"/>) to the point (<see cref="DistanceResult.PointB"/>).</summary>
    public DistanceResult Result { get; }

    /// <inheritdoc />
    public override string ToString() => Body < 0 ? "none" : $"body {Body}: {Result}";
}
