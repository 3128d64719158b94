namespace URWPGSim2D.Engine.Simulation.Kinematics;

/// <summary>
/// The tail joints' travelling wave of the original (its <c>DeflectionAngleOfJoint</c>): for joint
/// i = 1, 2, 3 from the body backward, φᵢ = 1.2·radians(Aᵢ(V)·sin(2π·f(V)·t + p + λᵢ) − 0.4·Dᵢ(T)),
/// with t the match time in seconds, f(V) the speed gear's tail-beat frequency
/// (<see cref="SpeedTable.TailFrequency"/>), the amplitude Aᵢ = k(V)·20° + (8°, 10°, 10°)ᵢ with k by
/// VCode 0.1, 0.15, 0.2, 0.25, 0.3, 0.35 and 0.3 from VCode 6 on, the turn offset
/// Dᵢ = c(T)·60°·(0.4, 0.85, 1)ᵢ (c the turn gear's bend factor, <see cref="TurnTable.BendFactor"/>;
/// joint 1 bends least), the lags λ = 0, 80, 59 added as radians and p the fish's own phase.
/// Each φᵢ is measured from the body axis. Computed every cycle from the decision's codes.
/// </summary>
internal static class TailWave
{
    private const double DegToRad = Math.PI / 180.0;

    private static readonly float[] AmplitudeFactors =
    [
        0.1f, 0.15f, 0.2f, 0.25f, 0.3f, 0.35f, 0.3f, 0.3f, 0.3f, 0.3f, 0.3f, 0.3f, 0.3f, 0.3f, 0.3f, 0.3f,
    ];

    private static readonly float[] AmplitudeBases = [8f, 10f, 10f];

    private static readonly float[] TurnWeights = [0.4f, 0.85f, 1f];

    private static readonly float[] Lags = [0f, 80f, 59f];

    /// <summary>Amplitude Aᵢ(V) in degrees of joint <paramref name="joint"/> (0..2) at a speed gear.</summary>
    /// <param name="joint">Joint index 0, 1 or 2 (joint 1, 2 or 3).</param>
    /// <param name="vcode">Speed gear (clamped to 0..15).</param>
    public static float Amplitude(int joint, int vcode) =>
        (AmplitudeFactors[Math.Clamp(vcode, 0, 15)] * 20f) + AmplitudeBases[joint];

    /// <summary>Turn offset Dᵢ(T) in degrees of joint <paramref name="joint"/> (0..2) at a turn gear.</summary>
    /// <param name="joint">Joint index 0, 1 or 2.</param>
    /// <param name="tcode">Turn gear (clamped to 0..15).</param>
    public static float TurnOffset(int joint, int tcode) => TurnTable.BendFactor(tcode) * 60f * TurnWeights[joint];

    /// <summary>Joint angle φ of joint <paramref name="joint"/> (0..2), radians.</summary>
    /// <param name="joint">Joint index 0, 1 or 2.</param>
    /// <param name="vcode">The decision's speed gear.</param>
    /// <param name="tcode">The decision's turn gear.</param>
    /// <param name="time">Match time in seconds (cycle × 0.1).</param>
    /// <param name="phase">The fish's own phase p, radians (0 unless set).</param>
    public static float JointAngle(int joint, int vcode, int tcode, double time, float phase = 0f)
    {
        double wave = (2.0 * Math.PI * SpeedTable.TailFrequency(vcode) * time) + phase + Lags[joint];
        double degrees = (Amplitude(joint, vcode) * Math.Sin(wave)) - (0.4 * TurnOffset(joint, tcode));
        return (float)(1.2 * degrees * DegToRad);
    }
}
