using URWPGSim2D.Engine.Simulation.Kinematics;

namespace URWPGSim2D.Server.Tests.Simulation.Kinematics;

/// <summary>Fish locomotion in a match against the reference's speed and turn tables and its gear approach.</summary>
public sealed class SpeedAndTurnTests
{
    private static readonly float[] Speeds = [0f, 10f, 35f, 67f, 98f, 112f, 135f, 154f, 175f, 227f, 273f, 291f, 298f, 294f, 307f, 317f];
    private static readonly float[] Turns = [-0.394f, -0.297f, -0.244f, -0.192f, -0.137f, -0.087f, -0.052f, 0f, 0.052f, 0.087f, 0.137f, 0.192f, 0.244f, 0.297f, 0.349f, 0.349f];

    [Fact]
    public void TablesHoldTheReferenceValuesAndClampCodes()
    {
        for (int code = 0; code < 16; code++)
        {
            Assert.Equal(Speeds[code], SpeedTable.TargetSpeed(code));
            Assert.Equal(Turns[code], TurnTable.TargetTurnRate(code));
        }

        Assert.Equal(317f, SpeedTable.TargetSpeed(99));
        Assert.Equal(0f, SpeedTable.TargetSpeed(-3));
        Assert.Equal(-0.394f, TurnTable.TargetTurnRate(-1));
    }

    [Fact]
    public void AFishAtVCode14FromRestSwimsTheExponentialApproach()
    {
        // v_k = 307·(1 − 0.9^k); position after k cycles = −1000 + 0.1·Σ v_j = −1000 + 30.7·(k − 9·(1 − 0.9^k)):
        // k = 1: −996.93; k = 2: −991.097; k = 5: 30.7·(5 − 9·0.40951) = 40.3524 → −959.6476.
        var match = TestMatches.FromJson("""{"fish":[{"team":0,"position":[-1000,0],"decision":{"vcode":14,"tcode":7}}],"balls":[]}""");
        float[] speeds = [30.7f, 58.33f, 83.197f, 105.5773f, 125.7196f];
        float[] xs = [-996.93f, -991.097f, -982.7773f, -972.21957f, -959.6476f];
        for (int k = 0; k < 5; k++)
        {
            match.Step();
            Assert.Equal(speeds[k], match.World.Fish[0].Speed.Value, 1e-3f);
            Assert.Equal(xs[k], match.World.Fish[0].Position.X, 1e-2f);
            Assert.Equal(0f, match.World.Fish[0].Position.Y, 1e-3f);
        }
    }

    [Fact]
    public void TheHeadingTurnsAtTheApproachingRate()
    {
        // VCode 14, TCode 14 from rest: ω_k = 0.349·(1 − 0.9^k) = 0.0349, 0.06631, 0.094579 (the speed is ≥ 2 mm/s
        // from cycle 1, 30.7 mm/s); heading after 3 cycles = 0.1·(0.0349 + 0.06631 + 0.094579) = 0.0195789 rad.
        var match = TestMatches.FromJson("""{"fish":[{"team":0,"position":[0,0],"decision":{"vcode":14,"tcode":14}}],"balls":[]}""");
        match.Play(3);
        Assert.Equal(0.0195789f, match.World.Fish[0].Heading, 1e-6f);
        Assert.Equal(0.094579f, match.World.Fish[0].Turn.Value, 1e-6f);
    }

    [Fact]
    public void AFishTurnsOnlyOnceItsSpeedReachesTwoMillimetresPerSecond()
    {
        // VCode 1 (10 mm/s): v = 1, 1.9, 2.71. TCode 0: the approach gives −0.0394 rad/s every cycle, set to 0 while
        // v < 2 (cycles 1, 2); in cycle 3 the heading turns by −0.0394·0.1 = −0.00394 rad.
        var match = TestMatches.FromJson("""{"fish":[{"team":0,"position":[0,0],"decision":{"vcode":1,"tcode":0}}],"balls":[]}""");
        match.Play(2);
        Assert.Equal(0f, match.World.Fish[0].Heading);
        Assert.Equal(0f, match.World.Fish[0].Turn.Value);
        match.Step();
        Assert.Equal(2.71f, match.World.Fish[0].Speed.Value, 1e-4f);
        Assert.Equal(-0.00394f, match.World.Fish[0].Heading, 1e-6f);
    }

    [Fact]
    public void BelowTwoMillimetresPerSecondAFishCannotTurn()
    {
        var match = TestMatches.FromJson("""{"fish":[{"team":0,"position":[0,0],"heading":0.5,"decision":{"vcode":0,"tcode":0}}],"balls":[]}""");
        match.Play(20);
        Assert.Equal(0.5f, match.World.Fish[0].Heading, 1e-6f);
        Assert.Equal(0f, match.World.Fish[0].Turn.Value);
    }
}
