using URWPGSim2D.Collision.Queries;

namespace URWPGSim2D.Collision.Motion;

/// <summary>The body of a <see cref="MotionWorld"/> nearest a point, and how near.</summary>
public readonly struct NearestBody
{
    internal NearestBody(BodyId body, in DistanceResult result)
    {
        Body = body;
        Result = result;
    }

    /// <summary>The nearest body, or <c>default(BodyId)</c> (<see cref="BodyId.IsNull"/>) when the motion world has no body.</summary>
    public BodyId Body { get; }

    /// <summary>The distance from the body (<see cref="DistanceResult.PointA"/>, on the fish's leaf <see cref="DistanceResult.PartA"/>) to the point (<see cref="DistanceResult.PointB"/>).</summary>
    public DistanceResult Result { get; }

    /// <inheritdoc />
    public override string ToString() => Body.IsNull ? "none" : $"{Body}: {Result}";
}
