using URWPGSim2D.Engine.Items.RelayWithBall;

namespace URWPGSim2D.Server.Tests.Items;

/// <summary>
/// 带球接力 against the numbers of the original's <c>SpeedRelayWithBallIn12Meter</c>: the layout from the
/// field's numbers, the pockets that end the legs, the channels each fish and the ball must keep to,
/// the put-back places and the variable.
/// </summary>
public sealed class RelayWithBallTests() : ItemTests(new RelayWithBallItem())
{
    [Fact]
    public void TheLayoutIsTheOriginals()
    {
        var s = Item.CreateScenario(1);
        Assert.Equal((3000f, 2000f, false), (s.FieldLength, s.FieldWidth, s.GoalBlocks));
        Assert.Equal(new[] { (0, new Vector2(-1135f, 0f), 0f), (0, new Vector2(1135f, 0f), MathF.PI) }, s.Fish.Select(f => (f.Team, f.Position, f.Heading)).ToArray());
        var ball = Assert.Single(s.Balls);
        Assert.Equal((new Vector2(-268f, -317f), 58f), (ball.Position, ball.Radius));

        // 3000 - 300 - 1200 = 1500 by 225 at z -/+(1000 - 400 - 112.5); the post 400 by 2000 - 450 - 800.
        (float X, float Z, float Length, float Width)[] original = [(0, -487.5f, 1500, 225), (0, 0, 400, 750), (0, 487.5f, 1500, 225)];
        Assert.Equal(original, s.Obstacles.Select(o => (o.Center.X, o.Center.Y, o.Length, o.Width)).ToArray());
        Assert.Equal(("带球接力", 1, 2), (Item.ChineseName, Item.TeamCount, Item.FishPerTeam));
    }

    [Fact]
    public void LegsEndInThePocketsInTurn()
    {
        var match = ItemTestMatches.Build(Item, 6000);
        var r = (RelayWithBallReferee)match.Referee!;
        var ball = match.World.Balls[0];

        // Leg 1 ends in the right pocket: 0 < x < 692, |z| < 317 (the left pocket does not count).
        Placement.Place(ball, new Vector2(-400f, 0f));
        match.JudgeCycle();
        Placement.Place(ball, new Vector2(692f, 0f));
        match.JudgeCycle();
        Placement.Place(ball, new Vector2(691f, 317f));
        match.JudgeCycle();
        Assert.Equal(0, r.Legs);
        Placement.Place(ball, new Vector2(691f, 316f));
        match.JudgeCycle();
        Assert.Equal((1, 4, "1"), (r.Legs, r.LegCycle(1), r.Variables["FinishedSingleTripCount"]));

        // Leg 2 in the left pocket, leg 3 in the right, leg 4 in the left; then the match is over.
        match.JudgeCycle();
        Assert.Equal(1, r.Legs);
        Placement.Place(ball, new Vector2(-691f, -316f));
        match.JudgeCycle();
        Placement.Place(ball, new Vector2(300f, 0f));
        match.JudgeCycle();
        Placement.Place(ball, new Vector2(-300f, 0f));
        match.JudgeCycle();
        Assert.Equal((4, 4), (r.Legs, r.Scores[0]));
        Assert.True(match.IsOver);
        Assert.Equal(new MatchOutcome(0, "relay done in 0.8 s"), r.Outcome);
        Assert.Equal(new[] { "leg", "leg", "leg", "leg", "end" }, r.Events.Select(e => e.Kind).ToArray());
    }

    [Fact]
    public void EachFishKeepsToItsChannel()
    {
        var match = ItemTestMatches.Build(Item, 6000);
        var r = (RelayWithBallReferee)match.Referee!;
        var w = match.World;

        // Fish 0 may use the top channel, not the bottom one (|x| < 692, z > 658).
        Placement.Place(w.Fish[0], new Vector2(0f, -800f), 0f);
        Placement.Place(w.Fish[1], new Vector2(0f, 800f), 0f);
        match.JudgeCycle();
        Placement.Place(w.Fish[0], new Vector2(691f, 658f), 0f);
        match.JudgeCycle();
        Assert.Empty(r.Events);
        Placement.Place(w.Fish[0], new Vector2(691f, 659f), 0f);
        match.JudgeCycle();
        Assert.Equal((new Vector2(-1180f, 0f), 0f), (w.Fish[0].Position, w.Fish[0].Heading));

        // Fish 1 not the top one (z < -658): back at (1500 - 320, 0) facing -x.
        Placement.Place(w.Fish[1], new Vector2(-691f, -659f), 0f);
        match.JudgeCycle();
        Assert.Equal((new Vector2(1180f, 0f), MathF.PI), (w.Fish[1].Position, MathF.Abs(w.Fish[1].Heading)));
        Assert.Equal(new[] { (0, "foul"), (1, "foul") }, r.Events.Select(e => (e.Fish, e.Kind)).ToArray());
    }

    [Fact]
    public void TheBallKeepsToEachLegsChannel()
    {
        var match = ItemTestMatches.Build(Item, 6000);
        var r = (RelayWithBallReferee)match.Referee!;
        var ball = match.World.Balls[0];

        // Leg 1: either channel.
        Placement.Place(ball, new Vector2(0f, -800f));
        match.JudgeCycle();
        Placement.Place(ball, new Vector2(0f, 800f));
        match.JudgeCycle();
        Assert.Empty(r.Events);

        // Leg 2: not the top channel; back at (268, -317).
        Placement.Place(ball, new Vector2(400f, 0f));
        match.JudgeCycle();
        Placement.Place(ball, new Vector2(0f, 800f));
        match.JudgeCycle();
        Assert.Single(r.Events);
        Placement.Place(ball, new Vector2(-691f, -659f));
        match.JudgeCycle();
        Assert.Equal(new Vector2(268f, -317f), ball.Position);

        // Leg 3: not the bottom channel; back at (-268, -317).
        Placement.Place(ball, new Vector2(-400f, 0f));
        match.JudgeCycle();
        Placement.Place(ball, new Vector2(0f, 659f));
        match.JudgeCycle();
        Assert.Equal(new Vector2(-268f, -317f), ball.Position);
        Assert.Equal(new[] { "leg", "foul", "leg", "foul" }, r.Events.Select(e => e.Kind).ToArray());
        Assert.Equal((-1, 0), (r.Events[1].Fish, r.Events[1].Ball));
    }

    [Fact]
    public void TheTimeEndsTheMatch()
    {
        var match = ItemTestMatches.Build(Item, 20);
        match.JudgeCycles(20);
        Assert.True(match.IsOver);
        Assert.Equal(new MatchOutcome(-1, "relay not done (0 of 4 legs)"), match.Referee!.Outcome);
    }

    [Fact]
    public void TheDemoFreesTheBallAndTakesItIntoTheTopChannel()
    {
        var match = ItemTestMatches.Build(Item, 3000, "demo", 1, noise: true);
        bool inChannel = false;
        while (!match.IsOver)
        {
            match.Step();
            inChannel |= RelayWithBallLayout.InChannel(match.World.Balls[0].Position, top: true);
        }

        Assert.True(inChannel, "the ball never reached the top channel");
    }
}
