namespace URWPGSim2D.Strategies;

/// <summary>Where a ray first enters a body of the match (the answer of <see cref="FieldSensor.RayCast"/>).</summary>
/// <param name="Body">The body entered, or <see cref="SensedBody.None"/> when the ray enters none.</param>
/// <param name="Result">
/// The entry: point, outward normal, fraction of the way (0 at the ray's start, 1 at its end) and, for
/// a fish, the part entered. Plane vectors, mm (X = world X, Y = world Z).
/// </param>
public readonly record struct SensedHit(SensedBody Body, RayCastResult Result)
{
    /// <summary>Whether the ray enters a body.</summary>
    public bool Hit => Body.Exists;

    /// <inheritdoc />
    public override string ToString() => Hit ? $"{Body}: {Result}" : "miss";
}
