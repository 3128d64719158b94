using URWPGSim2D.Engine.Simulation.Kinematics;

namespace URWPGSim2D.Engine.Simulation;

/// <summary>
/// The locomotion stage of a cycle: each fish's speed and angular speed take one step of the
/// original's gear approach (<see cref="GearApproach"/>) toward the decision's VCode and TCode, then
/// the angular speed is 0 while |v| &lt; 2 mm/s; the tail joints take the wave's pose for the cycle
/// from the decision's codes (<see cref="TailWave"/>), and the cycle's motion is set: velocity v·u along the heading and
/// angular velocity ω. With noise on, the reference's disturbances are added to this cycle's motion
/// (heading ±v²/500000 rad, position ±30·|ω| mm per axis, a moving ball ±1 mm per axis) so the
/// motion world carries them like any other motion. Balls keep their velocity; their drag is applied
/// after the cycle's travel (<see cref="BallMotion"/>).
/// </summary>
internal static class Locomotion
{
    /// <summary>Sets every body's motion for the cycle that ends at match time <paramref name="endTime"/> (s).</summary>
    public static void Apply(World world, SeededRandom? noise, double endTime)
    {
        const float dt = PhysicsConstants.CycleSeconds;
        foreach (var f in world.Fish)
        {
            if (f.OutOfPlay)
            {
                Still(f);
                continue;
            }

            var d = f.Decision;
            f.Speed.Advance(d.VCode, SpeedTable.Speeds);
            f.Turn.Advance(d.TCode, TurnTable.Rates);
            if (MathF.Abs(f.Speed.Value) < PhysicsConstants.MinimumTurningSpeed)
            {
                f.Turn.Value = 0f;
            }

            float joint1 = TailWave.JointAngle(0, d.VCode, d.TCode, endTime, f.TailPhase);
            float joint2 = TailWave.JointAngle(1, d.VCode, d.TCode, endTime, f.TailPhase);
            float joint3 = TailWave.JointAngle(2, d.VCode, d.TCode, endTime, f.TailPhase);
            if (world.TailSweeps)
            {
                f.TurnJoints(joint1, joint2, joint3);
            }
            else
            {
                f.SetJoints(joint1, joint2, joint3);
            }

            Vector2 drift = Vector2.Zero;
            float angularDrift = 0f;
            if (noise is not null)
            {
                float v = f.Speed.Value;
                angularDrift = noise.NextSigned() * (v * v / 500000f) / dt;
                float reach = 30f * MathF.Abs(f.Turn.Value);
                drift = new Vector2(noise.NextSigned() * reach, noise.NextSigned() * reach) / dt;
            }

            f.SetMotion(f.Speed.Value * f.Forward, f.Turn.Value, drift, angularDrift);
        }

        foreach (var b in world.Balls)
        {
            b.NoiseVelocity = noise is not null && b.Velocity != Vector2.Zero
                ? new Vector2(noise.NextSigned(), noise.NextSigned()) / dt
                : Vector2.Zero;
        }
    }

    // A fish out of play (parked by an item) holds still: no propulsion, no noise.
    private static void Still(FishState f)
    {
        f.Speed.Reset(0f, SpeedTable.Speeds);
        f.Turn.Reset(0f, TurnTable.Rates);
        f.SetMotion(Vector2.Zero, 0f, Vector2.Zero, 0f);
    }

    /// <summary>
    /// After the cycle's travel: ball drag. A fish's contacts changed its motion for the rest of the
    /// cycle only; its swimming speed and turn rate (the gear approach state) are its own propulsion
    /// and carry on, so a fish pressed against a wall or another fish can still turn away.
    /// </summary>
    public static void Finish(World world)
    {
        foreach (var b in world.Balls)
        {
            b.Velocity = BallMotion.Decelerate(b.Velocity, PhysicsConstants.CycleSeconds);
        }
    }
}
