namespace URWPGSim2D.Strategies;

/// <summary>The body of the match nearest a point, and how near (the answer of <see cref="FieldSensor.Nearest"/>).</summary>
/// <param name="Body">The nearest body, or <see cref="SensedBody.None"/> when no body was looked at.</param>
/// <param name="Result">
/// The gap (0 when the point is inside the body), <see cref="DistanceResult.PointA"/> the body's point
/// nearest the point (with the fish part in <see cref="DistanceResult.PartA"/>), <see cref="DistanceResult.PointB"/>
/// the point itself. Plane vectors, mm (X = world X, Y = world Z).
/// </param>
public readonly record struct SensedDistance(SensedBody Body, DistanceResult Result)
{
    /// <summary>The gap, mm (+∞ when no body was looked at).</summary>
    public float Distance => Body.Exists ? Result.Distance : float.PositiveInfinity;

    /// <inheritdoc />
    public override string ToString() => Body.Exists ? $"{Body}: {Result}" : "none";
}
