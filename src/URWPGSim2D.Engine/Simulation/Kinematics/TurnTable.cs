namespace URWPGSim2D.Engine.Simulation.Kinematics;

/// <summary>
/// The turn gears of the original core: TCode 0..15 maps to a target angular speed in rad/s
/// (7 = straight; below 7 turns left, i.e. toward −Z at heading 0; above 7 turns right).
/// A positive angular speed turns the heading from +X toward +Z.
/// </summary>
internal static class TurnTable
{
    /// <summary>Number of gears (TCode 0..15).</summary>
    public const int Gears = 16;

    /// <summary>The gear that swims straight.</summary>
    public const int Straight = 7;

    private static readonly float[] Targets =
    [
        -0.394f, -0.297f, -0.244f, -0.192f, -0.137f, -0.087f, -0.052f, 0f,
        0.052f, 0.087f, 0.137f, 0.192f, 0.244f, 0.297f, 0.349f, 0.349f,
    ];

    private static readonly float[] Bends =
    [
        -1f, -0.9f, -0.8f, -0.7f, -0.5f, -0.3f, -0.1f, 0f, 0.1f, 0.2f, 0.3f, 0.5f, 0.7f, 0.8f, 0.9f, 1f,
    ];

    /// <summary>The table itself: target angular speed (rad/s) by TCode 0..15.</summary>
    public static ReadOnlySpan<float> Rates => Targets;

    /// <summary>Largest target angular speed magnitude of the table, rad/s.</summary>
    public const float MaximumTurnRate = 0.394f;

    /// <summary>Target angular speed (rad/s) of a turn gear; the code is clamped to 0..15.</summary>
    /// <param name="tcode">Turn gear.</param>
    public static float TargetTurnRate(int tcode) => Targets[Math.Clamp(tcode, 0, Gears - 1)];

    /// <summary>Tail bend factor c in −1..1 of a turn gear (the tail wave's turn offset Dᵢ = c·60·(0.4, 0.85, 1)ᵢ degrees).</summary>
    /// <param name="tcode">Turn gear.</param>
    public static float BendFactor(int tcode) => Bends[Math.Clamp(tcode, 0, Gears - 1)];
}
