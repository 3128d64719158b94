namespace URWPGSim2D.Engine.Simulation.Kinematics;

/// <summary>
/// The speed gears of the original core: VCode 0..15 maps to a target forward speed in mm/s.
/// </summary>
internal static class SpeedTable
{
    /// <summary>Number of gears (VCode 0..15).</summary>
    public const int Gears = 16;

    private static readonly float[] Targets =
    [
        0f, 10f, 35f, 67f, 98f, 112f, 135f, 154f, 175f, 227f, 273f, 291f, 298f, 294f, 307f, 317f,
    ];

    private static readonly float[] Frequencies =
    [
        0f, 0.375f, 0.5f, 0.625f, 0.75f, 0.875f, 1f, 1.125f, 1.5f, 1.625f, 1.75f, 1.875f, 2f, 2.125f, 2.125f, 2.125f,
    ];

    /// <summary>The table itself: target speed (mm/s) by VCode 0..15.</summary>
    public static ReadOnlySpan<float> Speeds => Targets;

    /// <summary>The highest target speed of the table, mm/s (VCode 15).</summary>
    public const float MaximumSpeed = 317f;

    /// <summary>Target forward speed (mm/s) of a speed gear; the code is clamped to 0..15.</summary>
    /// <param name="vcode">Speed gear.</param>
    public static float TargetSpeed(int vcode) => Targets[Math.Clamp(vcode, 0, Gears - 1)];

    /// <summary>Tail-beat frequency (Hz) of a speed gear; the code is clamped to 0..15.</summary>
    /// <param name="vcode">Speed gear.</param>
    public static float TailFrequency(int vcode) => Frequencies[Math.Clamp(vcode, 0, Gears - 1)];
}
