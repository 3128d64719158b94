using URWPGSim2D.Engine.Items.NewBallGrab;

namespace URWPGSim2D.Server.Tests.Items;

/// <summary>
/// 抢球大作战 against the numbers of the original's <c>NewMatch2V2BallRace</c>: the ball grid, the
/// values, scores that follow what lies in the boxes now, half time, and the clutch shot.
/// </summary>
public sealed class NewBallGrabTests() : ItemTests(new NewBallGrabItem())
{
    // Wholly inside the left box: x in [-1152, -978] less the radius, |z| <= 507 - 58.
    private static readonly Vector2 LeftBox = new(-1065f, 0f);

    [Fact]
    public void TheLayoutIsTheOriginals()
    {
        var s = Item.CreateScenario(1);
        Assert.Equal((3000f, 2000f, false), (s.FieldLength, s.FieldWidth, s.GoalBlocks));
        Vector2[] grid = [new(-120, -120), new(-120, 0), new(-120, 120), new(0, -120), new(0, 0), new(0, 120), new(120, -120), new(120, 0), new(120, 120)];
        Assert.Equal(grid, s.Balls.Select(b => b.Position).ToArray());
        Assert.All(s.Balls, b => Assert.Equal(58f, b.Radius));
        Assert.Equal(new double[] { 1, 1, 1, 1, 3, 1, 1, 1, 1 }, s.BallValues.ToArray());

        // The goal boxes and the fish of the original's formulas (as 抢球博弈's).
        (float X, float Z, float Length, float Width)[] boxes =
            [(-1065, 532, 174, 50), (-1065, -532, 174, 50), (1065, 532, 174, 50), (1065, -532, 174, 50), (-964, 0, 29, 1109), (964, 0, 29, 1109)];
        Assert.Equal(boxes, s.Obstacles.Select(o => (o.Center.X, o.Center.Y, o.Length, o.Width)).ToArray());
        Assert.Equal(new[] { new Vector2(-540, 135), new Vector2(-540, -135), new Vector2(540, 135), new Vector2(540, -135) }, s.Fish.Select(f => f.Position).ToArray());
        Assert.Equal(("抢球大作战", 2, 2), (Item.ChineseName, Item.TeamCount, Item.FishPerTeam));
    }

    [Fact]
    public void TheScoreIsWhatLiesInTheBoxNow()
    {
        var match = ItemTestMatches.Build(Item, 6000);
        var r = (NewBallGrabReferee)match.Referee!;
        var w = match.World;

        // Ball 4 (3 points) and ball 0 in the left box: team 0 has 4; ball 1 in the right box: team 1 has 1.
        Placement.Place(w.Balls[4], LeftBox);
        Placement.Place(w.Balls[0], LeftBox + new Vector2(0f, 200f));
        Placement.Place(w.Balls[1], -LeftBox);
        match.JudgeCycle();
        Assert.Equal(new[] { 4, 1 }, r.Scores);

        // Wholly inside only: the ball's edge on the bar's inner end (x + 58 <= -978).
        Placement.Place(w.Balls[0], new Vector2(-1035.9f, 0f));
        match.JudgeCycle();
        Assert.Equal(3, r.Scores[0]);
        Placement.Place(w.Balls[0], new Vector2(-1036f, 449f));
        match.JudgeCycle();
        Assert.Equal(4, r.Scores[0]);

        // Out again: the score goes down.
        Placement.Place(w.Balls[4], Vector2.Zero);
        match.JudgeCycle();
        Assert.Equal(new[] { 1, 1 }, r.Scores);
        Assert.Equal(new[] { "goal", "goal", "goal", "out", "goal", "out" }, r.Events.Select(e => e.Kind).ToArray());
        Assert.Equal(-3, r.Events[^1].Value);
    }

    [Fact]
    public void HalfTimeSwapsEndsAndMirrorsTheBallsTheTeamsKeepTheirScores()
    {
        var match = ItemTestMatches.Build(Item, 100);
        var r = (NewBallGrabReferee)match.Referee!;
        var w = match.World;
        Placement.Place(w.Balls[4], LeftBox);
        match.JudgeCycles(49);
        Assert.Equal(0, r.LeftTeam);
        match.JudgeCycle();
        Assert.Equal(1, r.LeftTeam);
        Assert.Equal(-LeftBox, w.Balls[4].Position);
        Assert.Equal(new Vector2(120f, 120f), w.Balls[0].Position);
        Assert.Equal(new[] { 3, 0 }, r.Scores);

        // Team 0's fish at the right end's start poses, facing -x.
        Assert.Equal(new Vector2(540f, 135f), w.Fish[0].Position);
        Assert.Equal(MathF.PI, MathF.Abs(w.Fish[0].Heading));
        Assert.Equal(new Vector2(-540f, 135f), w.Fish[2].Position);
        match.JudgeCycles(50);
        Assert.True(match.IsOver);
        Assert.Equal(new MatchOutcome(0, "higher score"), r.Outcome);
    }

    [Fact]
    public void ATieGoesToAClutchShotTheFirstLeadWins()
    {
        var match = ItemTestMatches.Build(Item, 100);
        var r = (NewBallGrabReferee)match.Referee!;
        var w = match.World;
        match.JudgeCycles(100);
        Assert.False(match.IsOver);
        Assert.True(r.ClutchShot);
        Assert.Equal("3", r.Variables["CompetitionPeriod"]);
        Assert.Equal(100 + NewBallGrabReferee.ClutchShotCycles, r.MaxCycles);

        // Half time of the clutch shot after 1500 cycles; then team 1 (now at the left) takes the lead.
        match.JudgeCycles(1499);
        Assert.Equal(1, r.LeftTeam);
        match.JudgeCycle();
        Assert.Equal(0, r.LeftTeam);
        match.JudgeCycles(10);
        Placement.Place(w.Balls[2], -LeftBox);
        match.JudgeCycle();
        Assert.True(match.IsOver);
        Assert.Equal(new MatchOutcome(1, "clutch shot"), r.Outcome);
        Assert.Equal(new[] { "half-time", "period", "half-time", "goal", "end" }, r.Events.Select(e => e.Kind).ToArray());
    }

    [Fact]
    public void AClutchShotWithoutALeadIsATie()
    {
        var match = ItemTestMatches.Build(Item, 10);
        match.JudgeCycles(10 + NewBallGrabReferee.ClutchShotCycles);
        Assert.True(match.IsOver);
        Assert.Equal(new MatchOutcome(-1, "tie"), match.Referee!.Outcome);
    }
}
