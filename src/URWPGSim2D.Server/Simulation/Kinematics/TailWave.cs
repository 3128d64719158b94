using System;

namespace URWPGSim2D.Server.Simulation.Kinematics;

/// <summary>
/// The tail-joint travelling wave: φᵢ = 1.2·(Aᵢ·sin(2π·f·t + lagᵢ) − 0.4·Tᵢ) degrees, converted to
/// radians, with t the match time in seconds, f the speed gear's tail-beat frequency, Tᵢ = c·60·kᵢ
/// degrees (c the turn gear's bend factor, k = 1, 0.85, 0.4) and lags 0°, 80°, 59°. The amplitude of
/// joint 1 grows linearly from 12° at VCode 1 to 17° at VCode 15 (0 at VCode 0); joints 2 and 3 use
/// 1.1 and 1.2 times that (our choice: the reference gives only joint 1). Each φᵢ is measured from
/// the body axis.
/// </summary>
public static class TailWave
{
    private const float DegToRad = MathF.PI / 180f;

    private static readonly float[] BendShares = [1f, 0.85f, 0.4f];

    private static readonly float[] AmplitudeShares = [1f, 1.1f, 1.2f];

    private static readonly float[] LagsDegrees = [0f, 80f, 59f];

    /// <summary>Amplitude of joint 1 in degrees for a speed gear.</summary>
    /// <param name="vcode">Speed gear (clamped to 0..15).</param>
    public static float Joint1Amplitude(int vcode)
    {
        int v = Math.Clamp(vcode, 0, 15);
        return v == 0 ? 0f : 12f + (5f * (v - 1) / 14f);
    }

    /// <summary>Joint angle φ of joint <paramref name="joint"/> (0..2), radians.</summary>
    /// <param name="joint">Joint index 0, 1 or 2.</param>
    /// <param name="vcode">Speed gear.</param>
    /// <param name="tcode">Turn gear.</param>
    /// <param name="time">Match time in seconds (cycles × 0.1).</param>
    public static float JointAngle(int joint, int vcode, int tcode, double time)
    {
        float amplitude = Joint1Amplitude(vcode) * AmplitudeShares[joint];
        double phase = (2.0 * Math.PI * SpeedTable.TailFrequency(vcode) * time) + (LagsDegrees[joint] * DegToRad);
        float bend = TurnTable.BendFactor(tcode) * 60f * BendShares[joint];
        float degrees = 1.2f * ((amplitude * (float)Math.Sin(phase)) - (0.4f * bend));
        return degrees * DegToRad;
    }
}
