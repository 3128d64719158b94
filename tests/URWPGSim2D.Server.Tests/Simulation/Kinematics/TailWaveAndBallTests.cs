using URWPGSim2D.Engine.Simulation.Kinematics;

namespace URWPGSim2D.Server.Tests.Simulation.Kinematics;

/// <summary>The tail wave and the ball's deceleration table.</summary>
public sealed class TailWaveAndBallTests
{
    [Fact]
    public void JointAnglesAtChosenTimesMatchTheReferenceFormula()
    {
        // φᵢ = 1.2·radians(Aᵢ·sin(2π·f·t + p + λᵢ) − 0.4·Dᵢ), λ = 0, 80, 59 rad, Aᵢ = k·20 + (8, 10, 10), Dᵢ = c·60·(0.4, 0.85, 1).
        // VCode 14 (f = 2.125, k = 0.3: A = 14, 16, 16), TCode 10 (c = 0.3: D = 7.2, 15.3, 18), t = 0.3 s, p = 0:
        //   joint 1: arg = 2π·0.6375 = 4.005531, sin = −0.760406, 14·(−0.760406) − 2.88 = −13.525684° → −0.283281 rad
        //   joint 2: arg = 84.005531, sin = 0.729418, 16·0.729418 − 6.12 = 5.550691° → 0.116253 rad
        //   joint 3: arg = 63.005531, sin = 0.172806, 16·0.172806 − 7.2 = −4.435108° → −0.092889 rad
        Assert.Equal(-0.283281f, TailWave.JointAngle(0, 14, 10, 0.3), 1e-5f);
        Assert.Equal(0.116253f, TailWave.JointAngle(1, 14, 10, 0.3), 1e-5f);
        Assert.Equal(-0.092889f, TailWave.JointAngle(2, 14, 10, 0.3), 1e-5f);

        // VCode 3 (f = 0.625, k = 0.25: A = 13, 15, 15), TCode 2 (c = −0.8: D = −19.2, −40.8, −48), t = 0.7 s, p = 0.5:
        //   joint 1: arg = 2π·0.4375 + 0.5 = 3.248894, sin = −0.107095, 13·(−0.107095) + 7.68 = 6.287763° → 0.131691 rad
        //   joint 2: arg = 83.248894, sin = 0.999995, 15·0.999995 + 16.32 = 31.319918° → 0.655963 rad
        //   joint 3: arg = 62.248894, sin = −0.550497, 15·(−0.550497) + 19.2 = 10.942544° → 0.229180 rad
        Assert.Equal(0.131691f, TailWave.JointAngle(0, 3, 2, 0.7, 0.5f), 1e-5f);
        Assert.Equal(0.655963f, TailWave.JointAngle(1, 3, 2, 0.7, 0.5f), 1e-5f);
        Assert.Equal(0.229180f, TailWave.JointAngle(2, 3, 2, 0.7, 0.5f), 1e-5f);
    }

    [Fact]
    public void AStoppedFishKeepsItsTailStillButBentByTheLags()
    {
        // VCode 0: f = 0, k = 0.1 (A = 10, 12, 12); TCode 7: c = 0. φ = 1.2·radians(A·sin(λ)) at any time:
        //   joint 1: sin 0 = 0 → 0; joint 2: 12·sin(80) = 12·(−0.993889) = −11.926664° → −0.249791 rad;
        //   joint 3: 12·sin(59) = 12·0.636738 = 7.640856° → 0.160030 rad.
        foreach (double t in new[] { 0.1, 12.3, 250.0 })
        {
            Assert.Equal(0f, TailWave.JointAngle(0, 0, 7, t), 1e-6f);
            Assert.Equal(-0.249791f, TailWave.JointAngle(1, 0, 7, t), 1e-5f);
            Assert.Equal(0.160030f, TailWave.JointAngle(2, 0, 7, t), 1e-5f);
        }
    }

    [Fact]
    public void InAMatchTheJointsTakeTheWaveOfTheDecisionEveryCycle()
    {
        // The cycle being played is k (t = 0.1·k): after 3 steps at VCode 14, TCode 10 the joints are the t = 0.3 values above.
        var match = TestMatches.FromJson("""{"fish":[{"team":0,"position":[0,0],"decision":{"vcode":14,"tcode":10}}],"balls":[]}""");
        match.Play(3);
        var fish = match.World.Fish[0];
        Assert.Equal(-0.283281f, fish.Joint1, 1e-5f);
        Assert.Equal(0.116253f, fish.Joint2, 1e-5f);
        Assert.Equal(-0.092889f, fish.Joint3, 1e-5f);
    }

    [Fact]
    public void AScenarioSetsTheFishsOwnPhase()
    {
        // "tailPhase": 0.5 at VCode 3, TCode 2: after 7 cycles (t = 0.7 s) the joints are the p = 0.5 values above.
        var match = TestMatches.FromJson("""{"fish":[{"team":0,"position":[0,0],"tailPhase":0.5,"decision":{"vcode":3,"tcode":2}}],"balls":[]}""");
        match.Play(7);
        var fish = match.World.Fish[0];
        Assert.Equal(0.131691f, fish.Joint1, 1e-5f);
        Assert.Equal(0.655963f, fish.Joint2, 1e-5f);
        Assert.Equal(0.229180f, fish.Joint3, 1e-5f);
    }

    [Theory]
    [InlineData(0, 1f)]
    [InlineData(14, -1f)]
    public void TheTurnOffsetIsWeightedLeastOnJointOne(int tcode, float sign)
    {
        // Over one full beat at VCode 8 (1.5 Hz) the sine averages out, leaving −0.48·c·60·(0.4, 0.85, 1)ᵢ degrees.
        float[] weights = [0.4f, 0.85f, 1f];
        for (int joint = 0; joint < 3; joint++)
        {
            double mean = 0;
            const int samples = 600;
            for (int i = 0; i < samples; i++)
            {
                mean += TailWave.JointAngle(joint, 8, tcode, i / (1.5 * samples));
            }

            mean /= samples;
            float expected = -0.48f * TurnTable.BendFactor(tcode) * 60f * weights[joint] * System.MathF.PI / 180f;
            Assert.Equal(expected, (float)mean, 1e-3f);
            Assert.Equal(sign, System.MathF.Sign((float)mean));
        }
    }

    [Fact]
    public void TheWaveOscillatesAtTheGearFrequency()
    {
        // VCode 12 beats at 2 Hz: the angle repeats every 0.5 s and differs half a period later.
        float a = TailWave.JointAngle(0, 12, 7, 3.1);
        Assert.Equal(a, TailWave.JointAngle(0, 12, 7, 3.6), 1e-4f);
        Assert.NotEqual(a, TailWave.JointAngle(0, 12, 7, 3.35), 3);
    }

    [Theory]
    [InlineData(400f, 250f)]
    [InlineData(100f, 250f)]
    [InlineData(99f, 100f)]
    [InlineData(50f, 100f)]
    [InlineData(49f, 25f)]
    [InlineData(25f, 25f)]
    [InlineData(24.9f, 6.25f)]
    [InlineData(1f, 6.25f)]
    public void BallDecelerationFollowsTheTable(float speed, float deceleration)
    {
        Assert.Equal(deceleration, BallMotion.Deceleration(speed));
        Vector2 after = BallMotion.Decelerate(new Vector2(0f, speed), 0.1f);
        Assert.Equal(System.MathF.Max(0f, speed - (deceleration * 0.1f)), after.Y, 1e-4f);
        Assert.Equal(0f, after.X);
    }

    [Fact]
    public void AFreeBallTravelsThenDeceleratesAndStops()
    {
        // Each cycle: travel v·0.1 s, then lose a(v)·0.1 s of speed (independent re-computation of the table).
        var match = TestMatches.Balls(string.Empty, -500f, 0f, 200f, 0f);
        float x = -500f;
        float v = 200f;
        for (int k = 0; k < 80; k++)
        {
            match.Step();
            x += v * 0.1f;
            v = System.MathF.Max(0f, v - (BallMotion.Deceleration(v) * 0.1f));
            Assert.Equal(x, match.BallAt(0).X, 1e-2f);
            Assert.Equal(v, match.World.Balls[0].Velocity.X, 1e-3f);
        }

        Assert.Equal(0f, match.World.Balls[0].Velocity.X);
    }
}
