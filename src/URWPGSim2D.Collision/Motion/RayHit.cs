using URWPGSim2D.Collision.Queries;

namespace URWPGSim2D.Collision.Motion;

/// <summary>A ray's entry into one body of a <see cref="MotionWorld"/>.</summary>
public readonly struct RayHit
{
    internal RayHit(BodyId body, in RayCastResult result)
    {
        Body = body;
        Result = result;
    }

    /// <summary>The body entered, or <c>default(BodyId)</c> (<see cref="BodyId.IsNull"/>) when the ray enters none.</summary>
    public BodyId Body { get; }

    /// <summary>Where the ray enters it (<see cref="RayCastResult.Hit"/> false when it enters no body).</summary>
    public RayCastResult Result { get; }

    /// <inheritdoc />
    public override string ToString() => Body.IsNull ? "miss" : $"{Body}: {Result}";
}
