using URWPGSim2D.Collision.Fish;

namespace URWPGSim2D.Engine.Trace;

/// <summary>The trace's ids (fishN, ballN, obstacleN, wall, goalBlockN) and fish part names.</summary>
internal static class BodyNames
{
    /// <summary>The name of a fish part (−1 → null).</summary>
    public static string? Part(sbyte part) => part < 0 ? null : FishPartNames.Of((FishPart)part);

    /// <summary>The name of a fish part.</summary>
    public static string Part(FishPart part) => FishPartNames.Of(part);

    /// <summary>Id of body A of a pair.</summary>
    public static string A(in CandidatePair pair) => pair.Kind switch
    {
        PairKind.FishFish or PairKind.FishBall or PairKind.FishStatic or PairKind.FishWall => $"fish{pair.A}",
        _ => $"ball{pair.A}",
    };

    /// <summary>Id of body B of a pair.</summary>
    public static string B(World world, in CandidatePair pair) => pair.Kind switch
    {
        PairKind.FishFish => $"fish{pair.B}",
        PairKind.FishBall or PairKind.BallBall => $"ball{pair.B}",
        PairKind.FishStatic or PairKind.BallStatic => world.Statics[pair.B].IsGoalBlock ? $"goalBlock{world.Statics[pair.B].Id}" : $"obstacle{world.Statics[pair.B].Id}",
        _ => "wall",
    };
}
