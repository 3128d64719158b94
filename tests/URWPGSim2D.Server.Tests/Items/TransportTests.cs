using URWPGSim2D.Engine.Items.Transport;

namespace URWPGSim2D.Server.Tests.Items;

/// <summary>水中搬运: the layout of Match1V1Moving.cs, balls within 22 mm of their holes, the end at six, the demo.</summary>
public sealed class TransportTests() : ItemTests(new TransportItem())
{
    [Fact]
    public void TheLayoutIsMatch1V1MovingCs()
    {
        // Balls: row i = 1…3 at x = 160 (i + 3), z = −2r (i − 1) + 4r (j − 1) with r = 58.
        // Holes: x = −(3i − 3) · 80, z = −2 · 80 (i − 1) + 4 · 80 (j − 1).
        // Fish: f.LeftMm + 3 · BodyLength = −1500 + 480, z = ±3 · BodyWidth = ±135, heading 0.
        var s = TransportLayout.Scenario();
        Assert.Equal((3000f, 2000f, false), (s.FieldLength, s.FieldWidth, s.GoalBlocks));
        Assert.Empty(s.Obstacles);
        Assert.Equal(
            new[] { (640f, 0f), (800f, -116f), (800f, 116f), (960f, -232f), (960f, 0f), (960f, 232f) },
            s.Balls.Select(b => (b.Position.X, b.Position.Y)));
        Assert.All(s.Balls, b => Assert.Equal(58f, b.Radius));
        Assert.Equal(
            new[] { new Vector2(0f, 0f), new Vector2(-240f, -160f), new Vector2(-240f, 160f), new Vector2(-480f, -320f), new Vector2(-480f, 0f), new Vector2(-480f, 320f) },
            TransportLayout.Holes);
        Assert.Equal(new[] { (0, -1020f, 135f, 0f), (0, -1020f, -135f, 0f) }, s.Fish.Select(f => (f.Team, f.Position.X, f.Position.Y, f.Heading)));
        Assert.Equal((1, 2), (Item.TeamCount, Item.FishPerTeam));

        // The holes are drawn with radius 80 (zones "hole" 0–5).
        var zones = Item.CreateScenario(1).Zones;
        Assert.Equal(Enumerable.Range(0, 6), zones.Select(z => z.Id));
        Assert.All(zones, z => Assert.Equal(("hole", 80f), (z.Kind, z.Radius)));
    }

    [Theory]
    [InlineData(0f, true)]
    [InlineData(21f, true)]
    [InlineData(21.9f, true)]
    [InlineData(22f, false)] // the original: squared distance ≥ 484 is out
    [InlineData(23f, false)]
    public void ABallIsInItsHoleWithinTwentyTwoMillimetres(float distance, bool inHole)
    {
        var hole = TransportLayout.Holes[4];
        var dir = Vector2.Normalize(new Vector2(-3f, 4f));
        Assert.Equal(inHole, TransportLayout.InHole(hole + (dir * distance), hole));
    }

    [Fact]
    public void ABallTwentyOneMillimetresFromItsHoleScoresOnce()
    {
        var match = ItemTestMatches.Build(Item, 1000);
        Placement.Place(match.World.Balls[3], TransportLayout.Holes[3] + new Vector2(21f, 0f));
        match.JudgeCycle();
        var e = Assert.Single(match.EventsOf("ball-in-hole"));
        Assert.Equal((1, 0, 3, 1.0), (e.Cycle, e.Team, e.Ball, e.Value));
        Assert.Equal(new[] { 1 }, match.Referee!.Scores);
        Assert.Equal("1", match.Referee.Variables["Ball3InHole"]);

        // Out and back in: no second point.
        Placement.Place(match.World.Balls[3], new Vector2(0f, -700f));
        match.JudgeCycle();
        Placement.Place(match.World.Balls[3], TransportLayout.Holes[3]);
        match.JudgeCycle();
        Assert.Single(match.EventsOf("ball-in-hole"));
        Assert.Equal(1, match.Referee.Scores[0]);
        Assert.Equal(1, ((TransportReferee)match.Referee).LastGoalCycle);
    }

    [Fact]
    public void ABallTwentyThreeMillimetresAwayOrInAnotherBallsHoleDoesNotScore()
    {
        var match = ItemTestMatches.Build(Item, 1000);
        Placement.Place(match.World.Balls[3], TransportLayout.Holes[3] + new Vector2(0f, 23f));
        Placement.Place(match.World.Balls[0], TransportLayout.Holes[1]);
        match.JudgeCycle();
        Assert.Empty(match.EventsOf("ball-in-hole"));
        Assert.All(match.Referee!.Variables.Values, v => Assert.Equal("0", v));
    }

    [Fact]
    public void TheMatchEndsWhenAllSixAreIn()
    {
        var match = ItemTestMatches.Build(Item, 1000);
        match.JudgeCycles(4);
        for (int i = 0; i < 5; i++)
        {
            Placement.Place(match.World.Balls[i], TransportLayout.Holes[i]);
        }

        match.JudgeCycle();
        Assert.False(match.IsOver);
        Assert.Equal(new MatchOutcome(-1, "5 of 6 balls in, the last at 0.5 s"), match.Referee!.Outcome);
        match.JudgeCycles(2);
        Placement.Place(match.World.Balls[5], TransportLayout.Holes[5] + new Vector2(-15f, 15f));
        match.JudgeCycle();
        Assert.True(match.IsOver);
        Assert.Equal(8, Assert.Single(match.EventsOf("end")).Cycle);
        Assert.Equal(new MatchOutcome(0, "all 6 balls in, the last at 0.8 s"), match.Referee.Outcome);
        Assert.Equal(new[] { "Ball0InHole", "Ball1InHole", "Ball2InHole", "Ball3InHole", "Ball4InHole", "Ball5InHole" }, match.Referee.Variables.Keys);
        Assert.All(match.Referee.Variables.Values, v => Assert.Equal("1", v));
    }

    [Fact]
    public void WithoutBallsInTheMatchLastsItsTime()
    {
        var match = ItemTestMatches.Build(Item, 30);
        Assert.Equal(30, match.PlayAll());
        Assert.Equal(new MatchOutcome(-1, "no ball in its hole"), match.Referee!.Outcome);
        Assert.Equal(new[] { 0 }, match.Referee.Scores);
    }

    [Fact]
    public void TheDemoGetsBallsInWithinTenMinutesForEverySeed()
    {
        // Seeds 1–8 (measured: 4, 5, 5, 3, 5, 4, 4, 4 balls; 0 to 5 over seeds 1–16, docs/items.md):
        // every seed gets a ball in, and most get two or more.
        var scores = new System.Collections.Generic.List<int>();
        for (ulong seed = 1; seed <= 8; seed++)
        {
            var match = ItemMatches.Item("transport", seed);
            match.PlayAll();
            scores.Add(match.Referee!.Scores[0]);
            if (scores[^1] > 0)
            {
                Assert.Equal(match.EventsOf("ball-in-hole").Max(e => e.Cycle), ((TransportReferee)match.Referee).LastGoalCycle);
            }
        }

        string text = string.Join(", ", scores);
        Assert.True(scores.All(s => s >= 1), $"balls in per seed: {text}");
        Assert.True(scores.Count(s => s >= 2) >= 6, $"balls in per seed: {text}");
    }

    [Fact]
    public void TheSameSeedPlaysTheSameMatch()
    {
        int[] Play(ulong seed)
        {
            var m = ItemMatches.Item("transport", seed, 1500);
            m.PlayAll();
            return [.. m.Referee!.Scores, m.World.Cycle, (int)m.World.Balls[3].Position.X, (int)m.World.Balls[5].Position.Y, (int)m.World.Fish[1].Position.Y];
        }

        Assert.Equal(Play(7), Play(7));
        Assert.NotEqual(Play(7), Play(8));
    }
}
