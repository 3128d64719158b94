using URWPGSim2D.Engine.Items.PushBallViaChannel;

namespace URWPGSim2D.Server.Tests.Items;

/// <summary>
/// 协作过孔 against the numbers of the original's <c>TwoFishPushBallViaChannel</c>: the layout, the
/// touches per stage, the stage lines, the goal line and the variables.
/// </summary>
public sealed class PushBallViaChannelTests() : ItemTests(new PushBallViaChannelItem())
{
    [Fact]
    public void TheLayoutIsTheOriginals()
    {
        var s = Item.CreateScenario(1);
        Assert.Equal((3000f, 2000f, true), (s.FieldLength, s.FieldWidth, s.GoalBlocks));
        Assert.Equal(new[] { (0, new Vector2(-1030f, 280f)), (0, new Vector2(-1030f, 730f)) }, s.Fish.Select(f => (f.Team, f.Position)).ToArray());
        var ball = Assert.Single(s.Balls);
        Assert.Equal((new Vector2(1442f, 0f), 58f), (ball.Position, ball.Radius));

        // (3000 - 2 * 150) / 4 = 675; 2000 - 400 = 1600 wide; from the bottom, the top, the bottom.
        (float X, float Z, float Length, float Width)[] original = [(675, 200, 150, 1600), (0, -200, 150, 1600), (-675, 200, 150, 1600)];
        Assert.Equal(original, s.Obstacles.Select(o => (o.Center.X, o.Center.Y, o.Length, o.Width)).ToArray());
        Assert.Equal(("协作过孔", 1, 2), (Item.ChineseName, Item.TeamCount, Item.FishPerTeam));
    }

    [Fact]
    public void StartHeadingsAreWholeDegreesFromTheSeed()
    {
        for (ulong seed = 1; seed <= 20; seed++)
        {
            foreach (var f in Item.CreateScenario(seed).Fish)
            {
                float degrees = f.Heading * 180f / MathF.PI;
                Assert.InRange(degrees, 0f, 359.001f);
                Assert.Equal(MathF.Round(degrees), degrees, 0.001f);
            }

            Assert.Equal(Item.CreateScenario(seed).Fish.Select(f => f.Heading), Item.CreateScenario(seed).Fish.Select(f => f.Heading));
        }

        Assert.NotEqual(Item.CreateScenario(1).Fish[0].Heading, Item.CreateScenario(2).Fish[0].Heading);
    }

    [Fact]
    public void AStageScoresOnlyWhenBothFishTouchedTheBallInIt()
    {
        var match = ItemTestMatches.Build(Item, 6000);
        var r = (PushBallViaChannelReferee)match.Referee!;
        var w = match.World;

        // Stage 1: only fish 0 touches; the ball passes wall 0's left face (x 600): centre + 58 < 600.
        match.JudgeCycle(Judging.Touch(0, 0));
        Assert.True(r.Touched(0, 1));
        Assert.False(r.Touched(1, 1));
        Placement.Place(w.Balls[0], new Vector2(542f, -800f));
        match.JudgeCycle();
        Assert.Equal(1, r.Stage);
        Placement.Place(w.Balls[0], new Vector2(541.9f, -800f));
        match.JudgeCycle();
        Assert.Equal((2, 0), (r.Stage, r.Scores[0]));

        // Stage 2: both touch; past the middle wall's left face (x -75).
        match.JudgeCycle(Judging.Touch(1, 0), Judging.Touch(0, 0));
        Assert.False(r.Touched(1, 1));
        Assert.True(r.Touched(1, 2) && r.Touched(0, 2));
        Placement.Place(w.Balls[0], new Vector2(-134f, 800f));
        match.JudgeCycle();
        Assert.Equal((3, 1, 5), (r.Stage, r.Scores[0], r.ScoreCycle(1)));

        // Back right of the middle wall: the stage follows the furthest line passed now.
        Placement.Place(w.Balls[0], new Vector2(300f, 800f));
        match.JudgeCycle();
        Assert.Equal(2, r.Stage);
        Assert.Equal("2", r.Variables["ExecutingTaskNo"]);
        Assert.Equal("True", r.Variables["IsCollidedBallAndFish0AtStage2"]);
        Assert.Equal("False", r.Variables["IsCollidedBallAndFish1AtStage1"]);
        Assert.Equal(9, r.Variables.Count);
        Assert.Equal(new[] { "stage", "stage" }, r.Events.Select(e => e.Kind).ToArray());
        Assert.Equal(new[] { 0.0, 1.0 }, r.Events.Select(e => e.Value).ToArray());
    }

    [Fact]
    public void TheBallInTheLeftGoalEndsTheMatch()
    {
        var match = ItemTestMatches.Build(Item, 6000);
        var r = (PushBallViaChannelReferee)match.Referee!;
        var w = match.World;

        // Straight to the goal: every line is passed in one cycle, the stage is 4 when fish touch it.
        Placement.Place(w.Balls[0], new Vector2(-1000f, -800f));
        match.JudgeCycle();
        Assert.Equal(4, r.Stage);
        match.JudgeCycle(Judging.Touch(0, 0), Judging.Touch(1, 0));
        Placement.Place(w.Balls[0], new Vector2(-1408f, 0f));
        match.JudgeCycle();
        Assert.False(match.IsOver);
        Placement.Place(w.Balls[0], new Vector2(-1408.1f, 0f));
        match.JudgeCycle();
        Assert.True(match.IsOver);
        Assert.Equal((4, 1), (r.ThroughCycle, r.Scores[0]));
        Assert.Equal(new MatchOutcome(0, "ball in the left goal in 0.4 s (1 of 4 stages scored, score 1 reached in 0.4 s)"), r.Outcome);
        Assert.Equal(new[] { "stage", "stage", "stage", "stage", "through", "end" }, r.Events.Select(e => e.Kind).ToArray());
    }

    [Fact]
    public void TheTimeEndsTheMatch()
    {
        var match = ItemTestMatches.Build(Item, 30);
        match.JudgeCycles(29);
        Assert.False(match.IsOver);
        match.JudgeCycle();
        Assert.True(match.IsOver);
        Assert.Equal(new MatchOutcome(-1, "ball not in the left goal (0 of 4 stages scored)"), match.Referee!.Outcome);
    }

    [Fact]
    public void TheDemoScoresTheFirstStage()
    {
        var match = ItemTestMatches.Build(Item, 6000, "demo", 1, noise: true);
        match.PlayAll();
        var r = (PushBallViaChannelReferee)match.Referee!;
        Assert.True(r.StageScored(1), $"the demo scored {r.Scores[0]}");
    }
}
