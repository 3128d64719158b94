using System.Numerics;
using URWPGSim2D.Server.Simulation.Kinematics;
using URWPGSim2D.Server.Tests.Simulation;
using Xunit;

namespace URWPGSim2D.Server.Tests.Simulation.Kinematics;

/// <summary>The tail wave and the ball's deceleration table.</summary>
public sealed class TailWaveAndBallTests
{
    [Fact]
    public void AStoppedStraightFishHasAStraightTail()
    {
        for (int joint = 0; joint < 3; joint++)
        {
            Assert.Equal(0f, TailWave.JointAngle(joint, 0, 7, 12.3));
        }
    }

    [Theory]
    [InlineData(0, 1f)]
    [InlineData(14, -1f)]
    public void TheTailBendsTowardTheTurnOnAverage(int tcode, float sign)
    {
        // Over one full beat at VCode 8 (1.5 Hz) the sine averages out, leaving the bend −0.48·c·60·k degrees.
        double mean = 0;
        const int samples = 600;
        for (int i = 0; i < samples; i++)
        {
            mean += TailWave.JointAngle(0, 8, tcode, i / (1.5 * samples));
        }

        mean /= samples;
        float expected = -0.48f * TurnTable.BendFactor(tcode) * 60f * System.MathF.PI / 180f;
        Assert.Equal(expected, (float)mean, 1e-3f);
        Assert.Equal(sign, System.MathF.Sign((float)mean));
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
