using URWPGSim2D.Engine.Items.Rescue;

namespace URWPGSim2D.Server.Tests.Items;

/// <summary>急速救援: rescues, the half ending at two, the role swap, ties by times, the demo.</summary>
public sealed class RescueTests() : ItemTests(new RescueItem())
{
    private static readonly ulong[] Seeds = [1, 2, 3, 4, 5, 6, 7, 8];

    [Fact]
    public void TheDefendersSecondFishIsParkedOutOfPlay()
    {
        var match = ItemTestMatches.Build(Item, 100);
        var parked = match.World.Fish[3];
        Assert.True(parked.OutOfPlay);
        Assert.Equal(new Vector2(-2115f, 1591f), parked.Position);
        Assert.All(match.World.Fish.Take(3), f => Assert.False(f.OutOfPlay));
        match.Step();
        Assert.Equal(new Vector2(-2115f, 1591f), match.World.Fish[3].Position);
    }

    [Fact]
    public void ABallCentreInTheZoneScoresOnceForTheRescuer()
    {
        var match = ItemTestMatches.Build(Item, 1000);
        Placement.Place(match.World.Balls[0], new Vector2(1900f, 450f));
        match.Step();
        var rescue = Assert.Single(match.EventsOf("rescue"));
        Assert.Equal((1, 0, 0, 1.0), (rescue.Cycle, rescue.Team, rescue.Ball, rescue.Value));
        Assert.Equal(new[] { 1, 0 }, match.Referee!.Scores);
        match.Step();
        match.Step();
        Assert.Single(match.EventsOf("rescue"));
        Assert.Equal(1, match.Referee.Scores[0]);
    }

    [Fact]
    public void ABallJustOutsideTheZoneDoesNotScore()
    {
        // Centre at x = 1849 (zone from 1850) and at rest: nothing.
        var match = ItemTestMatches.Build(Item, 1000);
        Placement.Place(match.World.Balls[0], new Vector2(1849f, 0f));
        Placement.Place(match.World.Balls[1], new Vector2(2000f, -560f));
        match.Step();
        Assert.Empty(match.EventsOf("rescue"));
    }

    [Fact]
    public void AHalfEndsAtTwoRescuesAndTheRolesSwap()
    {
        var match = ItemTestMatches.Build(Item, 1000);
        Placement.Place(match.World.Balls[0], new Vector2(2000f, 0f));
        match.Step();
        Assert.Equal(1, match.Referee!.Half);
        Placement.Place(match.World.Balls[1], new Vector2(2000f, 200f));
        match.Step();

        var half = Assert.Single(match.EventsOf("half-time"));
        Assert.Equal(2, half.Cycle);
        Assert.Equal(2, match.Referee.Half);
        var r = (RescueReferee)match.Referee;
        Assert.Equal(1, r.Rescuer);

        // Team 1 now rescues from x = 1350; team 0 defends from (−1350, 0) with fish 1 parked; balls back at their starts.
        var w = match.World;
        Assert.Equal(new Vector2(1350f, 700f), w.Fish[2].Position);
        Assert.Equal(new Vector2(1350f, -700f), w.Fish[3].Position);
        Assert.False(w.Fish[2].OutOfPlay || w.Fish[3].OutOfPlay);
        Assert.Equal(new Vector2(-1350f, 0f), w.Fish[0].Position);
        Assert.True(w.Fish[1].OutOfPlay);
        Assert.Equal(new Vector2(-2115f, 1591f), w.Fish[1].Position);
        Assert.Equal(new Vector2(-1350f, 1050f), w.Balls[0].Position);
        Assert.Equal(new Vector2(-1350f, -1050f), w.Balls[1].Position);

        // The second half is a full half (500 cycles), counted from its start.
        match.Play(499);
        Assert.False(match.IsOver);
        match.Step();
        Assert.True(match.IsOver);
        Assert.Equal(502, w.Cycle);
        Assert.Equal(new MatchOutcome(0, "higher score"), match.Referee.Outcome);
    }

    [Fact]
    public void HalfTimeComesAtHalfTheCyclesWithoutRescues()
    {
        var match = ItemTestMatches.Build(Item, 20);
        match.Play(9);
        Assert.Empty(match.EventsOf("half-time"));
        match.Step();
        Assert.Equal(10, Assert.Single(match.EventsOf("half-time")).Cycle);
        Assert.Equal(20, match.PlayAll() + 10);
        Assert.Equal(new MatchOutcome(-1, "tie"), match.Referee!.Outcome);
    }

    [Fact]
    public void EqualScoresGoToTheEarlierRescueCountedFromEachHalfsStart()
    {
        // Team 0 rescues ball 0 at cycle 5 of its half; team 1 rescues ball 1 at cycle 3 of its half.
        var match = ItemTestMatches.Build(Item, 40);
        match.Play(4);
        Placement.Place(match.World.Balls[0], new Vector2(2000f, 0f));
        match.Play(16);
        Assert.Equal(20, Assert.Single(match.EventsOf("half-time")).Cycle);
        match.Play(2);
        Placement.Place(match.World.Balls[1], new Vector2(2000f, 0f));
        match.PlayAll();

        var r = (RescueReferee)match.Referee!;
        Assert.Equal(new[] { 1, 1 }, r.Scores);
        Assert.Equal(5, r.Time(0, 1));
        Assert.Equal(3, r.Time(1, 1));
        Assert.Equal(new MatchOutcome(1, "equal scores, earlier first rescue"), r.Outcome);
    }

    [Fact]
    public void TheRescuersFirstContactWithABallIsItsTouch()
    {
        // Fish 0 of team 0 starts with its head 30 mm from ball 0 and swims into it.
        var match = ItemTestMatches.Build(Item, 1000, "fixed", edit: s => s with
        {
            Fish = s.Fish.Select((f, i) => i == 0 ? f with { Position = new Vector2(-1350f + 170f, 1050f), Decision = new Decision(6, 7) } : f with { Strategy = "idle" }).ToList(),
        });
        int touched = 0;
        for (int k = 1; k <= 40 && touched == 0; k++)
        {
            match.Step();
            touched = match.EventsOf("touch").Count;
        }

        var touch = Assert.Single(match.EventsOf("touch"));
        Assert.Equal((0, 0, 0), (touch.Team, touch.Fish, touch.Ball));
        Assert.Equal(touch.Cycle, ((RescueReferee)match.Referee!).Time(0, 0));
    }

    [Fact]
    public void TheDemoRoutesStartAtTheBallsKeepClearOfTheWallsAndEndInTheZone()
    {
        var walls = RescueLayout.Walls.Select((c, i) => new ObstacleView(i, ObstacleKind.Rectangle, c, RescueLayout.WallLength, RescueLayout.WallWidth, 0f, 0f)).ToArray();
        for (int ball = 0; ball < 2; ball++)
        {
            var route = RescueRoutes.Route(ball).ToArray();
            Assert.Equal(RescueLayout.Balls[ball], route[0]);
            Assert.True(RescueLayout.InZone(route[^1]));

            // Every point along it, 5 mm apart: the ball's surface keeps 65 mm from walls and pool sides.
            for (int i = 0; i + 1 < route.Length; i++)
            {
                int steps = (int)(Vector2.Distance(route[i], route[i + 1]) / 5f) + 1;
                for (int k = 0; k <= steps; k++)
                {
                    Vector2 p = Vector2.Lerp(route[i], route[i + 1], k / (float)steps);
                    float clear = walls.Min(w => OutsideOf(w, p));
                    clear = System.MathF.Min(clear, System.MathF.Min((RescueLayout.FieldLength / 2f) - System.MathF.Abs(p.X), (RescueLayout.FieldWidth / 2f) - System.MathF.Abs(p.Y)));
                    Assert.True(clear - RescueLayout.BallRadius >= 65f, $"ball {ball} at {p}: {clear - RescueLayout.BallRadius:F1} mm from a wall");
                }
            }
        }
    }

    [Fact]
    public void TheDemoRescuesInItsHalfAgainstAnIdleDefenderForMostSeeds()
    {
        // Team 0 rescues in the first half (3000 of 6000 cycles); team 1 stands still. The demo is
        // meant to rescue at least one ball in a clear majority of seeds (it does in all of 1–24 as
        // measured, docs/items.md); small changes of contact timing must not break that.
        var results = Seeds.Select(seed =>
        {
            var match = ItemTestMatches.Build(Item, 6000, "demo", seed, noise: true, edit: Idle(team: 1));
            match.Play(3000);
            return (seed, rescued: match.Referee!.Scores[0]);
        }).ToList();

        Assert.True(results.Count(r => r.rescued >= 1) >= 6, Describe(results));
        Assert.True(results.Sum(r => r.rescued) >= 10, Describe(results));
    }

    [Fact]
    public void TheSecondHalfsRescuerRescuesAgainstAnIdleDefenderForMostSeeds()
    {
        // Team 1 rescues in the second half, from the other team's places; team 0 stands still.
        var results = Seeds.Select(seed =>
        {
            var match = ItemTestMatches.Build(Item, 6000, "demo", seed, noise: true, edit: Idle(team: 0));
            match.PlayAll();
            return (seed, rescued: match.Referee!.Scores[1]);
        }).ToList();

        Assert.True(results.Count(r => r.rescued >= 1) >= 6, Describe(results));
    }

    [Fact]
    public void DemoAgainstDemoEachTeamRescuesInItsHalfForMostSeeds()
    {
        // The 10-minute match of `run --item rescue`: the defender guards the zone.
        var results = Seeds.Select(seed =>
        {
            var match = ItemTestMatches.Build(Item, 6000, "demo", seed, noise: true);
            match.PlayAll();
            var r = (RescueReferee)match.Referee!;
            Assert.All(match.EventsOf("rescue"), e => Assert.Equal(e.Cycle <= 3000 ? 0 : 1, e.Team));
            return (seed, first: r.Scores[0], second: r.Scores[1]);
        }).ToList();

        string text = string.Join(", ", results.Select(r => $"seed {r.seed}: {r.first}-{r.second}"));
        Assert.True(results.Count(r => r.first >= 1) >= 6, text);
        Assert.True(results.Count(r => r.second >= 1) >= 6, text);
    }

    [Fact]
    public void TheSameSeedPlaysTheSameMatch()
    {
        string Play(ulong seed)
        {
            var m = ItemTestMatches.Build(Item, 6000, "demo", seed, noise: true);
            m.Play(3000);
            var w = m.World;
            return string.Join(";", m.Referee!.Events.Select(e => $"{e.Cycle}:{e.Kind}:{e.Ball}"))
                + string.Join(";", w.Balls.Select(b => b.Position.ToString())) + string.Join(";", w.Fish.Select(f => f.Position.ToString()));
        }

        string first = Play(7);
        Assert.Equal(first, Play(7));
        Assert.NotEqual(first, Play(8));
    }

    private static System.Func<URWPGSim2D.Engine.Scenario.ScenarioDefinition, URWPGSim2D.Engine.Scenario.ScenarioDefinition> Idle(int team) =>
        s => s with { Fish = s.Fish.Select(f => f.Team == team ? f with { Strategy = "idle" } : f).ToList() };

    private static string Describe(System.Collections.Generic.IEnumerable<(ulong Seed, int Rescued)> results) =>
        string.Join(", ", results.Select(r => $"seed {r.Seed}: {r.Rescued}"));

    // Distance from a point to an unrotated rectangular wall (0 inside it).
    private static float OutsideOf(in ObstacleView wall, System.Numerics.Vector2 p) =>
        System.Numerics.Vector2.Max(System.Numerics.Vector2.Abs(p - wall.Center) - (new System.Numerics.Vector2(wall.Length, wall.Width) * 0.5f), System.Numerics.Vector2.Zero).Length();
}
