using URWPGSim2D.Engine.Items.Survival;

namespace URWPGSim2D.Server.Tests.Items;

/// <summary>生存挑战: the layout of MatchTransfer.cs, catches, the half ending at three, the role swap, the speed cap, ties, the demo.</summary>
public sealed class SurvivalTests() : ItemTests(new SurvivalItem())
{
    // World fish indices: team 0's fish 0–3 are 0–3, team 1's fish 0–3 are 4–7.
    private const int Hunter0 = 0, Guard1 = 4, Prey1 = 5, Prey2 = 6, Prey3 = 7;

    [Fact]
    public void TheLayoutIsMatchTransferCs()
    {
        // 4500 × 3000, no balls, obs1–obs3 400 × 400 at (0, 0), (0, −700), (0, 700); the left team's
        // fish 0 at f.LeftMm + 3 · BodyLength = −2250 + 480, its fish 1–3 at (−2115 / −1715 / −1315, 1591);
        // the right team at (450, 0) and (1600, −800 / 0 / 800), facing π.
        var s = SurvivalLayout.Scenario();
        Assert.Equal((4500f, 3000f, false), (s.FieldLength, s.FieldWidth, s.GoalBlocks));
        Assert.Empty(s.Balls);
        Assert.Equal(new[] { (0f, 0f), (0f, -700f), (0f, 700f) }, s.Obstacles.Select(o => (o.Center.X, o.Center.Y)));
        Assert.All(s.Obstacles, o => Assert.Equal((ObstacleKind.Rectangle, 400f, 400f, 0f), (o.Kind, o.Length, o.Width, o.Heading)));
        Assert.Equal(
            new[]
            {
                (0, -1770f, 0f, 0f), (0, -2115f, 1591f, 0f), (0, -1715f, 1591f, 0f), (0, -1315f, 1591f, 0f),
                (1, 450f, 0f, MathF.PI), (1, 1600f, -800f, MathF.PI), (1, 1600f, 0f, MathF.PI), (1, 1600f, 800f, MathF.PI),
            },
            s.Fish.Select(f => (f.Team, f.Position.X, f.Position.Y, f.Heading)));

        // A caught fish j goes to (2415 − 300 j, 1591).
        Assert.Equal(new[] { new Vector2(2115f, 1591f), new Vector2(1815f, 1591f), new Vector2(1515f, 1591f) }, new[] { 1, 2, 3 }.Select(SurvivalLayout.CaughtPlace));
        Assert.Equal((2, 4), (Item.TeamCount, Item.FishPerTeam));
    }

    [Fact]
    public void TheHuntersTeamMatesAreParkedOutOfPlay()
    {
        var match = ItemTestMatches.Build(Item, 100);
        var w = match.World;
        Assert.All(w.Fish.Skip(1).Take(3), f => Assert.True(f.OutOfPlay));
        Assert.False(w.Fish[Hunter0].OutOfPlay);
        Assert.All(w.Fish.Skip(4), f => Assert.False(f.OutOfPlay));
        match.Play(5);
        Assert.Equal(new Vector2(-1715f, 1591f), w.Fish[2].Position);
    }

    [Fact]
    public void TheHunterSwimmingIntoAPreyFishCatchesItAndParksIt()
    {
        // Team 0's fish 0 starts 130 mm head to head from team 1's fish 1 (facing it, at 1600, −800) and swims straight.
        var match = ItemTestMatches.Build(Item, 1000, "idle", edit: s => s with
        {
            Fish = s.Fish.Select((f, i) => i == Hunter0 ? f with { Position = new Vector2(1250f, -800f), Strategy = "fixed", Decision = new Decision(6, 7) } : f).ToList(),
        });
        for (int k = 0; k < 60 && match.EventsOf("catch").Count == 0; k++)
        {
            match.Step();
        }

        var c = Assert.Single(match.EventsOf("catch"));
        Assert.Equal((0, Prey1, 1.0), (c.Team, c.Fish, c.Value));
        var prey = match.World.Fish[Prey1];
        Assert.True(prey.OutOfPlay);
        Assert.Equal(new Vector2(2115f, 1591f), prey.Position);
        Assert.Equal(new[] { 1, 0 }, match.Referee!.Scores);
        Assert.Equal("1", match.Referee.Variables["IsYellowFish2Caught"]);
        match.Play(10);
        Assert.Single(match.EventsOf("catch"));
        Assert.Equal(new Vector2(2115f, 1591f), prey.Position);
    }

    [Fact]
    public void OnlyTheHuntersContactWithAPreyFishIsACatch()
    {
        var match = ItemTestMatches.Build(Item, 1000);
        match.JudgeCycle(Meet(Hunter0, Guard1), Meet(Prey1, Prey2), Meet(Guard1, Prey3));
        Assert.Empty(match.EventsOf("catch"));
        match.JudgeCycle(Meet(Hunter0, Prey3));
        var c = Assert.Single(match.EventsOf("catch"));
        Assert.Equal((2, 0, Prey3), (c.Cycle, c.Team, c.Fish));
        Assert.Equal(new Vector2(1515f, 1591f), match.World.Fish[Prey3].Position);
        match.JudgeCycle(Meet(Hunter0, Prey3));
        Assert.Single(match.EventsOf("catch"));
        Assert.Equal(new[] { 1, 0 }, match.Referee!.Scores);
    }

    [Fact]
    public void ThreeCatchesEndTheHalfAndTheRolesSwap()
    {
        var match = ItemTestMatches.Build(Item, 1000);
        match.JudgeCycle(Meet(Hunter0, Prey1));
        match.JudgeCycle(Meet(Hunter0, Prey2));
        Assert.Equal(1, match.Referee!.Half);
        match.JudgeCycle(Meet(Prey3, Hunter0));

        var half = Assert.Single(match.EventsOf("half-time"));
        Assert.Equal((3, "half 1 over: hunter and hunted swap"), (half.Cycle, half.Text));
        var r = (SurvivalReferee)match.Referee;
        Assert.Equal((2, 1), (r.Half, r.Hunter));

        // Team 1 hunts from the left with its fish 0, its fish 1–3 parked; team 0 is hunted from the right.
        var w = match.World;
        Assert.Equal((new Vector2(-1770f, 0f), 0f, false), (w.Fish[Guard1].Position, w.Fish[Guard1].Heading, w.Fish[Guard1].OutOfPlay));
        Assert.Equal(new[] { (-2115f, 1591f, true), (-1715f, 1591f, true), (-1315f, 1591f, true) }, w.Fish.Skip(5).Select(f => (f.Position.X, f.Position.Y, f.OutOfPlay)));
        Assert.Equal(new[] { (450f, 0f, false), (1600f, -800f, false), (1600f, 0f, false), (1600f, 800f, false) }, w.Fish.Take(4).Select(f => (f.Position.X, f.Position.Y, f.OutOfPlay)));
        Assert.All(w.Fish.Take(4), f => Assert.Equal(MathF.PI, MathF.Abs(f.Heading), 5)); // facing −x (π wraps to −π)

        // Team 1's fish 0 catching team 0's fish 1–3 scores for team 1; the third catch ends the match.
        match.JudgeCycle(Meet(Hunter0, Guard1));
        Assert.Equal(new[] { 3, 0 }, r.Scores);
        match.JudgeCycle(Meet(1, Guard1));
        Assert.Equal("1", r.Variables["IsRedFish2Caught"]);
        Assert.Equal(new Vector2(2115f, 1591f), w.Fish[1].Position);
        match.JudgeCycle(Meet(2, Guard1), Meet(3, Guard1));
        Assert.True(match.IsOver);
        Assert.Equal(new[] { 3, 3 }, r.Scores);

        // Equal catches: team 0's last catch came 3 cycles into its half, team 1's 3 cycles into its own (cycle 6 − 3): a tie.
        Assert.Equal((3, 3), (r.LastCatch(0), r.LastCatch(1)));
        Assert.Equal(new MatchOutcome(-1, "tie"), r.Outcome);
    }

    [Fact]
    public void EqualCatchesGoToTheEarlierLastCatchCountedFromEachHalfsStart()
    {
        var match = ItemTestMatches.Build(Item, 40);
        match.JudgeCycles(4);
        match.JudgeCycle(Meet(Hunter0, Prey2));
        match.JudgeCycles(15);
        Assert.Equal(20, Assert.Single(match.EventsOf("half-time")).Cycle);
        match.JudgeCycles(2);
        match.JudgeCycle(Meet(2, Guard1));
        while (!match.IsOver)
        {
            match.JudgeCycle();
        }

        var r = (SurvivalReferee)match.Referee!;
        Assert.Equal(new[] { 1, 1 }, r.Scores);
        Assert.Equal((5, 3), (r.LastCatch(0), r.LastCatch(1)));
        Assert.Equal(new MatchOutcome(1, "equal catches, earlier last catch"), r.Outcome);
    }

    [Fact]
    public void HalfTimeComesAtHalfTheCyclesWithoutCatches()
    {
        var match = ItemTestMatches.Build(Item, 20);
        match.Play(9);
        Assert.Empty(match.EventsOf("half-time"));
        match.Step();
        Assert.Equal(10, Assert.Single(match.EventsOf("half-time")).Cycle);
        Assert.Equal(1, ((SurvivalReferee)match.Referee!).Hunter);
        Assert.Equal(20, match.PlayAll() + 10);
        Assert.Equal(new MatchOutcome(-1, "tie"), match.Referee.Outcome);
    }

    [Fact]
    public void FishOneToThreeSwimAtSpeedGearEightAtMost()
    {
        // Every fish asks for gear 15: the hunter and the free fish 0 keep it, the prey get 8, the parked fish stop.
        var match = ItemTestMatches.Build(Item, 1000, "fixed", edit: s => s with
        {
            Fish = s.Fish.Select((f, i) => f with { Position = new Vector2(-2000f, -1200f + (300f * i)), Heading = 0f, Decision = new Decision(15, 7) }).ToList(),
        });
        float fastestPrey = 0f, fastestFree = 0f;
        for (int k = 0; k < 40; k++)
        {
            match.Step();
            var w = match.World;
            Assert.Equal(15, w.Fish[Hunter0].Decision.VCode);
            Assert.Equal(15, w.Fish[Guard1].Decision.VCode);
            Assert.All(w.Fish.Skip(5), f => Assert.Equal(8, f.Decision.VCode));
            Assert.All(w.Fish.Skip(1).Take(3), f => Assert.Equal(0, f.Decision.VCode));
            fastestPrey = MathF.Max(fastestPrey, w.Fish.Skip(5).Max(f => f.Velocity.Length()));
            fastestFree = MathF.Max(fastestFree, w.Fish[Guard1].Velocity.Length());
        }

        // Gear 8 is 175 mm/s, gear 15 317 mm/s (the speed table).
        Assert.InRange(fastestPrey, 150f, 175.5f);
        Assert.True(fastestFree > 250f, $"the free fish reached only {fastestFree} mm/s");
    }

    [Fact]
    public void AScenarioFileMayMoveTheHunterAndKeepsTheParkedFishParked()
    {
        // Entries without a position keep the item's, even a parking place beyond the bottom wall;
        // a position given in the file must lie inside the field.
        var match = ItemMatches.FromJson("""{ "item": "生存挑战", "cycles": 100, "fish": [ {"position": [1200, -800]}, {}, {"strategy": "idle"} ] }""");
        var w = match.World;
        Assert.Equal(new Vector2(1200f, -800f), w.Fish[Hunter0].Position);
        Assert.Equal((new Vector2(-2115f, 1591f), true), (w.Fish[1].Position, w.Fish[1].OutOfPlay));
        Assert.Equal((new Vector2(-1715f, 1591f), true), (w.Fish[2].Position, w.Fish[2].OutOfPlay));
        var e = Assert.Throws<URWPGSim2D.Engine.Scenario.ScenarioException>(() => ItemMatches.FromJson("""{ "item": "survival", "fish": [ {}, {"position": [-2115, 1591]} ] }"""));
        Assert.Contains("fish[1].position", e.Message);
    }

    [Fact]
    public void TheVariablesAreTheOriginalsKeysInItsOrder()
    {
        var match = ItemTestMatches.Build(Item, 100);
        Assert.Equal(
            new[] { "IsYellowFish2Caught", "IsYellowFish3Caught", "IsYellowFish4Caught", "IsRedFish2Caught", "IsRedFish3Caught", "IsRedFish4Caught" },
            match.Referee!.Variables.Keys);
        Assert.All(match.Referee.Variables.Values, v => Assert.Equal("0", v));
    }

    [Theory]
    [InlineData(1UL)]
    [InlineData(2UL)]
    [InlineData(3UL)]
    public void TheDemoHunterCatchesAllThreeIdlePreyInItsHalf(ulong seed)
    {
        var match = ItemTestMatches.Build(Item, 6000, "demo", seed, noise: true, edit: s => s with
        {
            Fish = s.Fish.Select(f => f.Team == 1 ? f with { Strategy = "idle" } : f).ToList(),
        });
        match.PlayOut(3000);
        Assert.True(match.EventsOf("catch").Count == 3, $"seed {seed}: {match.EventsOf("catch").Count} catches in the first half");
        Assert.Equal(2, match.Referee!.Half);
    }

    [Theory]
    [InlineData(1UL)]
    [InlineData(2UL)]
    public void TheDemoCatchesAgainstTheFleeingDemoInBothHalves(ulong seed)
    {
        var match = ItemMatches.Item("survival", seed);
        match.PlayAll();
        Assert.True(match.Referee!.Scores.All(s => s >= 1), $"seed {seed}: scores {string.Join(", ", match.Referee.Scores)}");
    }

    [Fact]
    public void TheSameSeedPlaysTheSameMatch()
    {
        int[] Play(ulong seed)
        {
            var m = ItemMatches.Item("survival", seed, 2000);
            m.PlayAll();
            return [.. m.Referee!.Scores, m.World.Cycle, .. m.Referee.Events.Select(e => e.Cycle), (int)m.World.Fish[0].Position.X, (int)m.World.Fish[6].Position.Y];
        }

        Assert.Equal(Play(7), Play(7));
        Assert.NotEqual(Play(7), Play(8));
    }

    private static ContactRecord Meet(int a, int b) =>
        new(new CandidatePair(PairKind.FishFish, Math.Min(a, b), Math.Max(a, b), 1f), 1, 1, Vector2.Zero, Vector2.UnitX, Vector2.Zero, 0.5);
}
