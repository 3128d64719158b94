using System.Linq;
using System.Numerics;
using URWPGSim2D.Server.Items;
using URWPGSim2D.Server.Items.Rescue;
using URWPGSim2D.Server.Simulation;
using URWPGSim2D.Server.Tests.Simulation;
using Xunit;

namespace URWPGSim2D.Server.Tests.Items;

/// <summary>急速救援: rescues, the half ending at two, the role swap, ties by times, the demo.</summary>
public sealed class RescueTests
{
    private static readonly RescueItem Item = new();

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

    [Theory]
    [InlineData(1UL)]
    [InlineData(2UL)]
    [InlineData(3UL)]
    public void TheDemoBringsABallThroughTheLeftGapInItsHalfAgainstAnIdleDefender(ulong seed)
    {
        // The demo does not yet rescue within a 5-minute half (docs/items.md); it gets a ball from
        // its start in the left corner through the first gap of the slalom (x > −500).
        var match = ItemTestMatches.Build(Item, 6000, "demo", seed, noise: true, edit: s => s with
        {
            Fish = s.Fish.Select(f => f.Team == 1 ? f with { Strategy = "idle" } : f).ToList(),
        });
        float best = float.NegativeInfinity;
        for (int k = 0; k < 2990; k++)
        {
            match.Step();
            best = System.MathF.Max(best, System.MathF.Max(match.World.Balls[0].Position.X, match.World.Balls[1].Position.X));
        }

        Assert.True(best > -500f, $"seed {seed}: the balls got no farther than x = {best}");
        Assert.NotNull(((RescueReferee)match.Referee!).Time(0, 0));
    }

    [Fact]
    public void TheSameSeedPlaysTheSameMatch()
    {
        int[] Play(ulong seed)
        {
            var m = ItemTestMatches.Build(Item, 1200, "demo", seed, noise: true);
            m.PlayAll();
            return [.. m.Referee!.Scores, m.World.Cycle, m.Referee.Events.Count, (int)m.World.Balls[0].Position.X, (int)m.World.Fish[0].Position.Y];
        }

        Assert.Equal(Play(7), Play(7));
    }
}
