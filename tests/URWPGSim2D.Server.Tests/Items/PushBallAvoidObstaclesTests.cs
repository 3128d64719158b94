using URWPGSim2D.Engine.Items.PushBallAvoidObstacles;

namespace URWPGSim2D.Server.Tests.Items;

/// <summary>
/// 带球避障 against the numbers of the original's <c>SingleFishPushBallAvoidObstacles</c>: the
/// layout, the four legs and their thresholds, fouls (time off, put back, one per second), the black
/// line and the time less the penalties.
/// </summary>
public sealed class PushBallAvoidObstaclesTests() : ItemTests(new PushBallAvoidObstaclesItem())
{
    [Fact]
    public void TheLayoutIsTheOriginals()
    {
        var s = Item.CreateScenario(1);
        Assert.Equal((3000f, 2000f, false), (s.FieldLength, s.FieldWidth, s.GoalBlocks));
        var fish = Assert.Single(s.Fish);
        Assert.Equal((0, new Vector2(-1180f, 0f), 0f), (fish.Team, fish.Position, fish.Heading));
        var ball = Assert.Single(s.Balls);
        Assert.Equal((new Vector2(1030f, 0f), 58f), (ball.Position, ball.Radius));
        (float X, float Z, float Length, float Width)[] original =
        [
            (-480, 650, 10, 700), (-550, 270, 150, 60), (-550, 180, 150, 60), (-480, -160, 10, 700), (-480, -510, 150, 3),
            (480, -650, 10, 700), (550, -270, 150, 60), (550, -180, 150, 60), (480, 160, 10, 700), (480, 510, 150, 3),
        ];
        Assert.Equal(original, s.Obstacles.Select(o => (o.Center.X, o.Center.Y, o.Length, o.Width)).ToArray());
        Assert.All(s.Obstacles, o => Assert.Equal((ObstacleKind.Rectangle, 0f), (o.Kind, o.Heading)));
        Assert.Equal(("带球避障", 1, 1), (Item.ChineseName, Item.TeamCount, Item.FishPerTeam));
    }

    [Fact]
    public void PutBackPlacesFollowTheOriginalsFormulas()
    {
        // fish: obstacle x ∓ its length ∓ 160 (body length), line z ± its width + 45 (body width).
        Assert.Equal((new Vector2(-860f, -468f), 0f), PushBallAvoidObstaclesReferee.FishRestart(0));
        Assert.Equal((new Vector2(-170f, -462f), 0f), PushBallAvoidObstaclesReferee.FishRestart(1));
        Assert.Equal((new Vector2(790f, 558f), MathF.PI), PushBallAvoidObstaclesReferee.FishRestart(2));
        Assert.Equal((new Vector2(-790f, -462f), MathF.PI), PushBallAvoidObstaclesReferee.FishRestart(3));
        Assert.Null(PushBallAvoidObstaclesReferee.FishRestart(4));
        Assert.Equal(new Vector2(1030f, 0f), PushBallAvoidObstaclesReferee.BallRestart(2));
        Assert.Equal(Vector2.Zero, PushBallAvoidObstaclesReferee.BallRestart(3));
        Assert.Null(PushBallAvoidObstaclesReferee.BallRestart(4));
    }

    [Fact]
    public void TheLegsCountInOrderAtTheirThresholds()
    {
        var match = ItemTestMatches.Build(Item, 6000);
        var r = (PushBallAvoidObstaclesReferee)match.Referee!;
        var w = match.World;

        // Leg 1: x > -480 + 160.
        Placement.Place(w.Fish[0], new Vector2(-320f, -760f), 0f);
        match.JudgeCycle();
        Assert.Equal(0, r.Legs);
        Placement.Place(w.Fish[0], new Vector2(-319f, -760f), 0f);
        match.JudgeCycle();
        Assert.Equal((1, 2), (r.Legs, r.LegCycle(1)));

        // Leg 2: x > 480 + 160; only after leg 1, one leg per cycle.
        Placement.Place(w.Fish[0], new Vector2(641f, 760f), 0f);
        match.JudgeCycle();
        Assert.Equal(2, r.Legs);

        // Leg 3: fish x < 480 - 160 and ball x < 480 - 116.
        Placement.Place(w.Fish[0], new Vector2(319f, 760f), MathF.PI);
        Placement.Place(w.Balls[0], new Vector2(364f, 760f));
        match.JudgeCycle();
        Assert.Equal(2, r.Legs);
        Placement.Place(w.Balls[0], new Vector2(363f, 760f));
        match.JudgeCycle();
        Assert.Equal(3, r.Legs);

        // Leg 4: fish x < -480 - 160 and ball x < -480 - 116; the ball is then past the black line too.
        Placement.Place(w.Fish[0], new Vector2(-641f, -760f), MathF.PI);
        Placement.Place(w.Balls[0], new Vector2(-597f, -760f));
        match.JudgeCycle();
        Assert.Equal((4, 4), (r.Legs, r.Scores[0]));
        Assert.True(match.IsOver);
        Assert.Equal(new MatchOutcome(0, "ball past the black line in 0.6 s (4 of 4 legs, 0.0 s of penalties)"), r.Outcome);
        Assert.Equal(new[] { "leg", "leg", "leg", "leg", "through", "end" }, r.Events.Select(e => e.Kind).ToArray());
    }

    [Fact]
    public void TheBallIsThroughWhenWhollyPastTheBlackLine()
    {
        var match = ItemTestMatches.Build(Item, 6000);
        Placement.Place(match.World.Balls[0], new Vector2(-557f, 0f));
        match.JudgeCycle();
        Assert.False(match.IsOver);
        Placement.Place(match.World.Balls[0], new Vector2(-558f, 0f));
        match.JudgeCycle();
        Assert.True(match.IsOver);
        Assert.Equal(2, ((PushBallAvoidObstaclesReferee)match.Referee!).ThroughCycle);
    }

    [Fact]
    public void AFishFoulCostsFiveSecondsAndPutsItBackAndTheNextSecondIsQuiet()
    {
        var match = ItemTestMatches.Build(Item, 6000);
        var r = (PushBallAvoidObstaclesReferee)match.Referee!;
        var w = match.World;
        Placement.Place(w.Fish[0], new Vector2(-560f, 0f), 1f);
        match.JudgeCycle(Static(PairKind.FishStatic));
        Assert.Equal(50, r.PenaltyCycles);
        Assert.Equal((new Vector2(-860f, -468f), 0f), (w.Fish[0].Position, w.Fish[0].Heading));

        // Cycles 2–11 call no foul (the original clears its flag 10 cycles after, then checks again).
        for (int k = 0; k < 10; k++)
        {
            match.JudgeCycle(Static(PairKind.FishStatic));
        }

        Assert.Equal(50, r.PenaltyCycles);
        match.JudgeCycle(Static(PairKind.BallStatic), Static(PairKind.FishStatic));
        Assert.Equal(100, r.PenaltyCycles);
        Assert.Equal(new[] { "foul", "foul" }, r.Events.Select(e => e.Kind).ToArray());
        Assert.Equal(0, r.Events[1].Fish);
    }

    [Fact]
    public void ABallFoulCostsThreeSecondsAndPutsTheBallBack()
    {
        var match = ItemTestMatches.Build(Item, 6000);
        var r = (PushBallAvoidObstaclesReferee)match.Referee!;
        var w = match.World;
        Placement.Place(w.Balls[0], new Vector2(500f, 700f));
        match.JudgeCycle(Static(PairKind.BallStatic));
        Assert.Equal(30, r.PenaltyCycles);
        Assert.Equal(new Vector2(1030f, 0f), w.Balls[0].Position);
        Assert.Equal(-1, r.Events[0].Fish);
        Assert.Equal(0, r.Events[0].Ball);
    }

    [Fact]
    public void PenaltiesShortenTheMatch()
    {
        var match = ItemTestMatches.Build(Item, 100);
        match.JudgeCycle(Static(PairKind.FishStatic));
        match.JudgeCycles(48);
        Assert.False(match.IsOver);
        match.JudgeCycle();
        Assert.True(match.IsOver);
        Assert.Equal(50, match.World.Cycle);
        Assert.Equal(new MatchOutcome(-1, "ball not past the black line (0 of 4 legs, 5.0 s of penalties)"), match.Referee!.Outcome);
    }

    [Fact]
    public void TheDemoSwimsBothLegs()
    {
        var match = ItemTestMatches.Build(Item, 6000, "demo", 1, noise: true);
        match.PlayAll();
        var r = (PushBallAvoidObstaclesReferee)match.Referee!;
        Assert.True(r.Legs >= 2, $"the demo did {r.Legs} legs");
    }

    private static ContactRecord Static(PairKind kind) =>
        new(new CandidatePair(kind, 0, 0, 1f), 1, -1, Vector2.Zero, Vector2.UnitX, Vector2.Zero, 0.5);
}
