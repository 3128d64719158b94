using URWPGSim2D.Engine.Items.PlainScene;

namespace URWPGSim2D.Server.Tests.Items;

/// <summary>
/// The plain scene's rules, an item's referee like the others: a ball wholly inside a goal mouth
/// scores for the attacking team (a goal event) and goes back to its start; the match never ends by itself.
/// </summary>
public sealed class PlainSceneRefereeTests
{
    [Theory]
    [InlineData(1f, 0)]
    [InlineData(-1f, 1)]
    public void ABallInAGoalMouthScoresAndGoesBackToItsStart(float direction, int team)
    {
        // From x = ±1200 at 1,500 mm/s toward the end line: it rolls into the 150 mm deep mouth and stops at the back wall.
        var match = TestMatches.Balls(string.Empty, 1200f * direction, 0f, 1500f * direction, 0f);
        Assert.Null(match.Referee);
        Assert.IsType<PlainSceneReferee>(match.Rules);
        int scoredAt = 0;
        for (int k = 1; k <= 10 && scoredAt == 0; k++)
        {
            match.Step();
            scoredAt = match.Rules.Scores[team] > 0 ? k : 0;
        }

        Assert.True(scoredAt > 0, "the ball scored");
        Assert.Equal(0, match.Rules.Scores[1 - team]);
        var goal = Assert.Single(match.Rules.Events);
        Assert.Equal(new ItemEvent(scoredAt, "goal", team, -1, 0, 1.0, $"team {team} scores ball 0"), goal);
        Assert.Equal(new Vector2(1200f * direction, 0f), match.BallAt(0));
        Assert.Equal(Vector2.Zero, match.World.Balls[0].Velocity);
    }

    [Fact]
    public void ABallOnlyPartlyInTheMouthDoesNotScore()
    {
        // Centre 40 mm inside the mouth's entrance line: less than a radius, so not wholly inside.
        var match = TestMatches.Balls(string.Empty, 1390f, 0f, 0f, 0f);
        match.Step();
        Assert.Equal([0, 0], match.Rules.Scores);
        Assert.Empty(match.Rules.Events);
    }

    [Fact]
    public void TheMatchPlaysEveryCycleAskedForAndTheHigherScoreWins()
    {
        var match = TestMatches.Balls(string.Empty, 1200f, 0f, 1500f, 0f);
        for (int k = 0; k < 20; k++)
        {
            match.Step();
        }

        Assert.False(match.IsOver);
        Assert.Equal(1, match.Rules.Scores[0]);
        Assert.Equal(new MatchOutcome(0, "higher score"), match.Rules.Outcome);
    }

    [Fact]
    public void AGoalAllocatesNothing()
    {
        // Ball 0 scores for team 0 first, ball 1 for team 1 later. One match plays both goals
        // first (a goal's text is made once per process); in a second match the cycle of a goal
        // (the score, its event, the ball put back) allocates nothing.
        float[] balls = [1200f, 0f, 1500f, 0f, -800f, 0f, -1500f, 0f];
        var first = TestMatches.Balls(string.Empty, balls);
        first.Play(20);
        Assert.Equal([1, 1], first.Rules.Scores);

        var match = TestMatches.Balls(string.Empty, balls);
        long atGoal = -1;
        for (int k = 0; k < 20 && atGoal < 0; k++)
        {
            long before = GC.GetAllocatedBytesForCurrentThread();
            match.Step();
            long allocated = GC.GetAllocatedBytesForCurrentThread() - before;
            atGoal = match.Rules.Scores[1] == 1 ? allocated : -1;
        }

        Assert.Equal(2, match.Rules.Events.Count);
        Assert.Equal(0L, atGoal);
    }

    [Fact]
    public void TeamZeroAttacksTheRightGoal()
    {
        Assert.Equal(0, World.ScoringTeam(+1));
        Assert.Equal(1, World.ScoringTeam(-1));
    }
}
