namespace URWPGSim2D.Collision.Queries;

/// <summary>A ray's entry into one body of a <see cref="QueryWorld"/>.</summary>
public readonly struct BodyRayHit
{
    internal BodyRayHit(int body, in RayCastResult result)
    {
        Body = body;
        Result = result;
    }

    /// <summary>The body entered (its index in the world), or −1 when the ray enters none.</summary>
    public int Body { get; }

    /// <summary>Where the ray enters it (<see cref="RayCastResult.Hit"/> false when <see cref="Body"/> is −1).</summary>
    public RayCastResult Result { get; }

    /// <inheritdoc />
    public override string ToString() => Body < 0 ? "miss" : $"body {Body}: {Result}";
}
