namespace URWPGSim2D.Core;

/// <summary>
/// The measured gear tables of the original's fish, indexed by code 0..15. Strategies read them to
/// pick gears (for example <c>StrategyHelper.Helpers.Dribble</c>); the server's fish follow the same
/// tables. Writing to them changes nothing but the strategy's own copy of its beliefs.
/// </summary>
public static class DataBasedOnExperiment
{
    /// <summary>Target speed of VCode 0..15, mm/s.</summary>
    public static float[] VCodeAndVelocityTable = [0f, 10f, 35f, 67f, 98f, 112f, 135f, 154f, 175f, 227f, 273f, 291f, 298f, 294f, 307f, 317f];

    /// <summary>Target angular speed of TCode 0..15, rad/s (negative turns left, 7 is straight).</summary>
    public static float[] TCodeAndAngularVelocityTable =
        [-0.394f, -0.297f, -0.244f, -0.192f, -0.137f, -0.087f, -0.052f, 0f, 0.052f, 0.087f, 0.137f, 0.192f, 0.244f, 0.297f, 0.349f, 0.349f];
}
