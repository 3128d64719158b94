using System.Numerics;
using URWPGSim2D.Server.Simulation;
using Xunit;

namespace URWPGSim2D.Server.Tests.Simulation;

/// <summary>Goals: a ball wholly inside a goal mouth scores for the attacking team and goes back to its start.</summary>
public sealed class RulesTests
{
    [Theory]
    [InlineData(1f, 0)]
    [InlineData(-1f, 1)]
    public void ABallInAGoalMouthScoresAndGoesBackToItsStart(float direction, int team)
    {
        // From x = ±1200 at 1,500 mm/s toward the end line: it rolls into the 150 mm deep mouth and stops at the back wall.
        var match = TestMatches.Balls(string.Empty, 1200f * direction, 0f, 1500f * direction, 0f);
        int scoredAt = 0;
        for (int k = 1; k <= 10 && scoredAt == 0; k++)
        {
            match.Step();
            scoredAt = match.World.Goals[team] > 0 ? k : 0;
        }

        Assert.True(scoredAt > 0, "the ball scored");
        Assert.Equal(0, match.World.Goals[1 - team]);
        var goal = Assert.Single(match.Goals);
        Assert.Equal(new GoalEvent(scoredAt, 0, team), goal);
        Assert.Equal(new Vector2(1200f * direction, 0f), match.BallAt(0));
        Assert.Equal(Vector2.Zero, match.World.Balls[0].Velocity);
    }

    [Fact]
    public void ABallOnlyPartlyInTheMouthDoesNotScore()
    {
        // Centre 40 mm inside the mouth's entrance line: less than a radius, so not wholly inside.
        var match = TestMatches.Balls(string.Empty, 1390f, 0f, 0f, 0f);
        match.Step();
        Assert.Equal(0, match.World.Goals[0]);
        Assert.Equal(0, match.World.Goals[1]);
    }

    [Fact]
    public void TeamZeroAttacksTheRightGoal()
    {
        Assert.Equal(0, Rules.ScoringTeam(+1));
        Assert.Equal(1, Rules.ScoringTeam(-1));
    }
}
