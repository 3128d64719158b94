using URWPGSim2D.Collision.Motion;

namespace URWPGSim2D.Server.Tests.Items;

public sealed class BallGrabTests
{
    // Every fish idle, ball 0 (radius 38, value 3) where the test wants it, the others at rest far away.
    private const string Idle = """{"strategy":"idle"}""";

    [Fact]
    public void TheLayoutIsTheOriginals()
    {
        // Hand-copied from Match/TheNewMatch2V2.cs with r = 58, goal depth 150, field 3000 × 2000,
        // body length 160 and width 45 (the deployed fish), integer millimetres as the original computes them.
        var s = ItemRegistry.Find("抢球博弈")!.CreateScenario(1);
        Assert.Equal("ball-grab", s.Item!.Slug);
        Assert.Equal((3000f, 2000f, false), (s.FieldLength, s.FieldWidth, s.GoalBlocks));
        Assert.Equal(6000, s.Cycles);
        (int Team, float X, float Z, float Heading)[] fish = [(0, -540, 135, 0), (0, -540, -135, 0), (1, 540, 135, MathF.PI), (1, 540, -135, MathF.PI)];
        Assert.Equal(fish, s.Fish.Select(f => (f.Team, f.Position.X, f.Position.Y, f.Heading)).ToArray());
        (float X, float Z, float R, double Value)[] balls =
        [
            (0, -120, 38, 3), (0, 0, 38, 3), (0, 120, 38, 3),
            (-1420, -920, 78, 1), (1420, -920, 78, 1), (1420, 920, 78, 1), (-1420, 920, 78, 1),
            (0, -920, 58, 2), (0, 920, 58, 2),
        ];
        Assert.Equal(balls, s.Balls.Select((b, i) => (b.Position.X, b.Position.Y, b.Radius, s.BallValues[i])).ToArray());
        (float X, float Z, float L, float W)[] rectangles =
        [
            (-1065, 532, 174, 50), (-1065, -532, 174, 50), (1065, 532, 174, 50), (1065, -532, 174, 50),
            (-964, 0, 29, 1109), (964, 0, 29, 1109),
        ];
        Assert.Equal(rectangles, s.Obstacles.Select(o => (o.Center.X, o.Center.Y, o.Length, o.Width)).ToArray());
        Assert.All(s.Obstacles, o => Assert.Equal((ObstacleKind.Rectangle, 0f), (o.Kind, o.Heading)));
        Assert.Equal(new Vector2(-1152, -507), s.Zones[0].Min);
        Assert.Equal(new Vector2(-978, 507), s.Zones[0].Max);
        Assert.Equal((0, 1), (s.Zones[0].Team, s.Zones[1].Team));
        Assert.Equal(new Vector2(978, -507), s.Zones[1].Min);
        Assert.Equal(new Vector2(1152, 507), s.Zones[1].Max);
    }

    [Fact]
    public void AValueThreeBallInTheOwnBoxScoresThreeOnceNotAgainOnReEntry()
    {
        var match = ItemMatches.FromJson($$"""{"item":"ball-grab","fish":[{{Idle}},{{Idle}},{{Idle}},{{Idle}}],"balls":[{"position":[-1065,0]}]}""");
        match.Step();
        var referee = match.Referee();
        Assert.Equal([3, 0], referee.Scores);
        var goal = Assert.Single(referee.Events);
        Assert.Equal(new ItemEvent(1, "goal", 0, -1, 0, 3, "team 0 scores ball 0 (+3)"), goal);
        Assert.Equal("1", referee.Variables["Ball_0_Left_Status"]);
        Assert.Equal("0", referee.Variables["Ball_0_Right_Status"]);

        // Out of the box and back in: no second score for team 0.
        Placement.Place(match.World.Balls[0], new Vector2(-1300, 0));
        match.Step();
        Placement.Place(match.World.Balls[0], new Vector2(-1065, 100));
        match.Step();
        Assert.Equal([3, 0], referee.Scores);
        Assert.Single(referee.Events);
    }

    [Theory]
    [InlineData(-1065f, 0f, 38f, -1, true)]   // the middle of the left box
    [InlineData(-1114f, 0f, 38f, -1, true)]   // x − r = −1152, the bars' outer end
    [InlineData(-1115f, 0f, 38f, -1, false)]  // 1 mm beyond it
    [InlineData(-1016f, 0f, 38f, -1, true)]   // x + r = −978, the bars' inner end
    [InlineData(-1015f, 0f, 38f, -1, false)]
    [InlineData(-1065f, 469f, 38f, -1, true)] // z + r = 507, the lower bar's inner face
    [InlineData(-1065f, 470f, 38f, -1, false)]
    [InlineData(-1065f, -429f, 78f, -1, true)] // a large ball: z − r = −507
    [InlineData(-1065f, -430f, 78f, -1, false)]
    [InlineData(-1065f, 0f, 38f, 1, false)]   // the left box is not the right one
    [InlineData(1065f, 0f, 58f, 1, true)]
    public void ABallIsInABoxOnlyWhollyInside(float x, float z, float radius, int side, bool inside) =>
        Assert.Equal(inside, URWPGSim2D.Engine.Items.BallGrab.BallGrabLayout.InBox(new Vector2(x, z), radius, side));

    [Theory]
    [InlineData(-1065f, 0f, 0)]  // left box: team 0 in the first half
    [InlineData(1065f, 0f, 1)]   // right box: team 1
    [InlineData(-1300f, 0f, -1)] // in the channel beside the box: nobody
    [InlineData(0f, 500f, -1)]
    public void TheBoxAtATeamsEndScoresForIt(float x, float z, int team)
    {
        var match = ItemMatches.FromJson($$"""{"item":"ball-grab","fish":[{{Idle}},{{Idle}},{{Idle}},{{Idle}}],"balls":[{"position":[{{x}},{{z}}]}]}""");
        match.Step();
        var scores = match.Referee().Scores;
        Assert.Equal(team < 0 ? [0, 0] : team == 0 ? [3, 0] : [0, 3], scores);
    }

    [Fact]
    public void HalfTimeSwapsEndsMirrorsTheBallsAndTheStatusFollowsTheTeam()
    {
        var match = ItemMatches.FromJson($$"""{"item":"ball-grab","fish":[{{Idle}},{{Idle}},{{Idle}},{{Idle}}],"balls":[{"position":[-1065,0]},{"position":[300,-200]}]}""", cycles: 10);
        var referee = match.Referee();
        match.PlayOut(5);
        Assert.Equal(2, referee.Half);
        Assert.True(referee.SidesSwapped);
        Assert.Equal(ItemEvent.Plain(5, "half-time", "half 1 over: teams change ends"), referee.Events[1]);

        // Team t's fish j stands on the other team's fish j start pose; the balls went through the centre.
        var start = ItemRegistry.Find("ball-grab")!.CreateScenario(1).Fish;
        Assert.Equal(start[2].Position, match.World.Fish[0].Position);
        Assert.Equal(start[3].Position, match.World.Fish[1].Position);
        Assert.Equal(start[0].Position, match.World.Fish[2].Position);
        Assert.Equal(start[1].Position, match.World.Fish[3].Position);
        Assert.Equal(Angle.Wrap(MathF.PI), match.World.Fish[0].Heading);
        Assert.Equal(new Vector2(1065, 0), match.World.Balls[0].Position);
        Assert.Equal(new Vector2(-300, 200), match.World.Balls[1].Position);

        // Ball 0 is now in the right box, which is team 0's: team 0 scored it already, nothing more.
        // The left (team 1's) status shows team 1's record, the right one team 0's.
        Assert.Equal([3, 0], referee.Scores);
        Assert.Equal("0", referee.Variables["Ball_0_Left_Status"]);
        Assert.Equal("1", referee.Variables["Ball_0_Right_Status"]);

        // Ball 1 pushed into the left box now scores for team 1.
        Placement.Place(match.World.Balls[1], new Vector2(-1065, 0));
        match.Step();
        Assert.Equal([3, 3], referee.Scores);
        match.PlayOut(10);
        Assert.True(match.IsOver);
        Assert.Equal(10, match.World.Cycle);

        // Equal scores: team 0 scored first (cycle 1, team 1 at cycle 6).
        Assert.Equal(new MatchOutcome(0, "equal scores, earlier first score"), referee.Outcome);
        Assert.Equal("end", referee.Events[^1].Kind);
    }

    [Fact]
    public void NoScoreIsATie()
    {
        var match = ItemMatches.FromJson($$"""{"item":"ball-grab","fish":[{{Idle}},{{Idle}},{{Idle}},{{Idle}}]}""", cycles: 4);
        match.PlayOut(10);
        Assert.Equal(4, match.World.Cycle);
        Assert.Equal(new MatchOutcome(-1, "tie (no score)"), match.Referee().Outcome);
    }

    [Fact]
    public void TheVariablesHaveTheOriginalsKeys()
    {
        var match = ItemMatches.Item("ball-grab", 1);
        var keys = match.Referee().Variables.Keys.ToArray();
        Assert.Equal("CompetitionPeriod", keys[0]);
        Assert.Equal(Enumerable.Range(0, 9).Select(i => $"Ball_{i}_Left_Status").Concat(Enumerable.Range(0, 9).Select(i => $"Ball_{i}_Right_Status")), keys.Skip(1));
        Assert.All(keys, k => Assert.Equal(0, match.Referee().Variables.GetInt32(k)));
    }

    // The demo scores against an idle opponent within ten minutes. Measured (docs/items.md) over
    // seeds 1-48 it does at 45 of them (not at 12, 15 and 35); seeds 1-8 all score. The match is
    // played only until the demo's first score.
    [Theory]
    [InlineData(1UL)]
    [InlineData(2UL)]
    [InlineData(3UL)]
    [InlineData(4UL)]
    [InlineData(5UL)]
    [InlineData(6UL)]
    [InlineData(7UL)]
    [InlineData(8UL)]
    public void TheDemoScoresAgainstAnIdleOpponentWithinTenMinutes(ulong seed)
    {
        var item = ItemRegistry.Find("ball-grab")!;
        var match = ItemTestMatches.Build(item, 6000, "demo", seed, noise: true,
            edit: s => s with { Fish = s.Fish.Select(f => f.Team == 1 ? f with { Strategy = "idle" } : f).ToList() });
        while (!match.IsOver && match.Referee!.Scores[0] == 0)
        {
            match.Step();
        }

        Assert.True(match.Referee!.Scores[0] > 0, $"seed {seed}: the demo scored nothing against an idle opponent in ten minutes");
        Assert.True(match.World.Cycle <= 6000);
        Assert.Equal(0, match.Referee.Scores[1]);
    }

    [Fact]
    public void TheSameSeedGivesTheSameMatch()
    {
        string Run()
        {
            var match = ItemMatches.Item("ball-grab", 5, cycles: 400);
            match.PlayOut(400);
            var w = match.World;
            return string.Join(";", w.Fish.Select(f => $"{f.Position.X:R},{f.Position.Y:R},{f.Heading:R}"))
                + string.Join(";", w.Balls.Select(b => $"{b.Position.X:R},{b.Position.Y:R}"))
                + string.Join(",", match.Referee().Scores);
        }

        Assert.Equal(Run(), Run());
    }
}
