using URWPGSim2D.Collision.Motion;

namespace URWPGSim2D.Collision.Queries;

/// <summary>A ray's entry into one body of a <see cref="MotionWorld"/> or a <see cref="QueryWorld"/>.</summary>
public readonly struct BodyRayHit
{
    internal BodyRayHit(BodyId id, in RayCastResult result)
    {
        Id = id;
        Result = result;
    }

    /// <summary>The body entered (its index in the world, <see cref="BodyId.Index"/> of <see cref="Id"/>), or −1 when the ray enters none.</summary>
    public int Body => Id.Index;

    /// <summary>The body entered: its id in the motion world (for a <see cref="QueryWorld"/>, the one it keeps its bodies in), or <c>default</c> when the ray enters none.</summary>
    public BodyId Id { get; }

    /// <summary>Where the ray enters it (<see cref="RayCastResult.Hit"/> false when <see cref="Body"/> is −1).</summary>
    public RayCastResult Result { get; }

    /// <inheritdoc />
    public override string ToString() => Body < 0 ? "miss" : $"body {Body}: {Result}";
}
