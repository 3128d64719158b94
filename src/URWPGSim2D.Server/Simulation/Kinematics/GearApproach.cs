using System;

namespace URWPGSim2D.Server.Simulation.Kinematics;

/// <summary>
/// The one-tenth approach of a speed (or angular speed) to its gear's target: when the target
/// changes, the step becomes a tenth of the gap; each cycle the value moves one step toward the
/// target and snaps to it once the target is within one step. A full gear change therefore takes
/// ten cycles (1 s) and ends exactly on the table value.
/// </summary>
public struct GearApproach
{
    /// <summary>The current value (mm/s or rad/s).</summary>
    public float Value;

    /// <summary>The target it is moving to.</summary>
    public float Target;

    /// <summary>The size of one cycle's step, a tenth of the gap when the target was set.</summary>
    public float Step;

    /// <summary>Moves one cycle toward <paramref name="target"/>.</summary>
    /// <param name="target">Target value of the current gear.</param>
    public void Advance(float target)
    {
        float gap = target - Value;
        if (target != Target || Step <= 0f)
        {
            Target = target;
            Step = MathF.Abs(gap) * 0.1f;
        }

        if (MathF.Abs(gap) <= Step * 1.0001f)
        {
            Value = target;
        }
        else
        {
            Value += MathF.CopySign(Step, gap);
        }
    }

    /// <summary>Sets the value without a ramp (initial state, a stop).</summary>
    /// <param name="value">The new value.</param>
    public void Reset(float value)
    {
        Value = value;
        Step = 0f;
    }
}
