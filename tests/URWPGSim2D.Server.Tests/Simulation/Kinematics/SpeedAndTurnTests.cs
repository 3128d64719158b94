using System;
using URWPGSim2D.Server.Simulation.Kinematics;
using URWPGSim2D.Server.Tests.Simulation;
using Xunit;

namespace URWPGSim2D.Server.Tests.Simulation.Kinematics;

/// <summary>Fish locomotion against the reference's speed and turn tables.</summary>
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
    public void AFishAtVCode15ReachesExactly317MillimetresPerSecondInTenCyclesAndTravelsTheSum()
    {
        var match = TestMatches.FromJson("""{"fish":[{"team":0,"position":[-1000,0],"decision":{"vcode":15,"tcode":7}}],"balls":[]}""");
        float expectedX = -1000f;
        for (int k = 1; k <= 12; k++)
        {
            match.Step();
            float v = k >= 10 ? 317f : 31.7f * k;
            expectedX += v * 0.1f;
            Assert.Equal(v, match.World.Fish[0].Speed.Value, 1e-3f);
            Assert.Equal(expectedX, match.World.Fish[0].Position.X, 1e-2f);
            Assert.Equal(0f, match.World.Fish[0].Position.Y, 1e-3f);
        }
    }

    [Theory]
    [InlineData(0)]
    [InlineData(3)]
    [InlineData(7)]
    [InlineData(10)]
    [InlineData(14)]
    public void OnceSettledTheHeadingTurnsAtTheTableRate(int tcode)
    {
        var match = TestMatches.FromJson("{\"fish\":[{\"team\":0,\"position\":[0,0],\"decision\":{\"vcode\":4,\"tcode\":" + tcode + "}}],\"balls\":[]}");
        match.Play(30);
        float before = match.World.Fish[0].Heading;
        match.Step();
        float turned = Angle(match.World.Fish[0].Heading - before);
        Assert.Equal(Turns[tcode] * 0.1f, turned, 1e-5f);
        Assert.Equal(Turns[tcode], match.World.Fish[0].Turn.Value, 1e-5f);
    }

    [Fact]
    public void BelowTwoMillimetresPerSecondAFishCannotTurn()
    {
        var match = TestMatches.FromJson("""{"fish":[{"team":0,"position":[0,0],"heading":0.5,"decision":{"vcode":0,"tcode":0}}],"balls":[]}""");
        match.Play(20);
        Assert.Equal(0.5f, match.World.Fish[0].Heading, 1e-6f);
        Assert.Equal(0f, match.World.Fish[0].Turn.Value);
    }

    [Fact]
    public void TheApproachTakesTenthsOfTheGapAndSnaps()
    {
        var g = default(GearApproach);
        g.Reset(100f);
        g.Advance(300f);
        Assert.Equal(120f, g.Value, 1e-4f);
        for (int i = 0; i < 8; i++)
        {
            g.Advance(300f);
        }

        Assert.Equal(280f, g.Value, 1e-3f);
        g.Advance(300f);
        Assert.Equal(300f, g.Value);
        g.Advance(0f);
        Assert.Equal(270f, g.Value, 1e-3f);
    }

    private static float Angle(float a) => MathF.IEEERemainder(a, 2f * MathF.PI);
}
