using URWPGSim2D.Engine.Items.Polo;

namespace URWPGSim2D.Server.Tests.Items;

/// <summary>水球: goals wholly inside, kick-off, half time, fouls and sending off, dead ball, the tie deciders, the demo.</summary>
public sealed class PoloTests
{
    private static readonly PoloItem OneVsOne = new(1);
    private static readonly PoloItem ThreeVsThree = new(3);
    private static readonly PoloItem FiveVsFive = new(5);

    [Theory]
    [InlineData(-1408f, 0f, 1)] // wholly inside the left goal: x ≤ −1500 + 150 − 58
    [InlineData(1408f, -142f, 0)] // wholly inside the right goal, touching the mouth's edge
    [InlineData(-1407f, 0f, -1)] // 1 mm short
    [InlineData(1420f, 143f, -1)] // sticks out past z = 200
    public void AGoalIsTheBallWhollyInsideAGoal(float x, float z, int scorer)
    {
        var match = ItemTestMatches.Build(OneVsOne, 6000);
        Placement.Place(match.World.Balls[0], new Vector2(x, z));
        match.JudgeCycle();
        var goals = match.EventsOf("goal");
        if (scorer < 0)
        {
            Assert.Empty(goals);
            return;
        }

        Assert.Equal(scorer, Assert.Single(goals).Team);
        Assert.Equal(1, match.Referee!.Scores[scorer]);

        // Kick-off: ball at the centre, fish back at (∓1020, 0).
        Assert.Equal(Vector2.Zero, match.World.Balls[0].Position);
        Assert.Equal(new Vector2(-1020f, 0f), match.World.Fish[0].Position);
        Assert.Equal(new Vector2(1020f, 0f), match.World.Fish[1].Position);
    }

    [Fact]
    public void HalfTimeSwapsEndsSoTheSameGoalScoresForTheOtherTeam()
    {
        var match = ItemTestMatches.Build(OneVsOne, 600);
        match.JudgeCycles(300);
        Assert.Equal(300, Assert.Single(match.EventsOf("half-time")).Cycle);
        var r = (PoloReferee)match.Referee!;
        Assert.Equal(1, r.LeftTeam);
        Assert.Equal(new Vector2(1020f, 0f), match.World.Fish[0].Position);
        Assert.Equal(new Vector2(-1020f, 0f), match.World.Fish[1].Position);
        Placement.Place(match.World.Balls[0], new Vector2(-1420f, 0f));
        match.JudgeCycle();
        Assert.Equal(0, Assert.Single(match.EventsOf("goal")).Team);
    }

    [Fact]
    public void AFishFiveSecondsInItsOwnGoalWhileTheBallIsInTheZoneIsSentOff()
    {
        // Ball wholly in the left forbidden zone (x ≤ −1008, |z| ≤ 442); team 0's fish centre in its goal (x ≤ −1350, |z| ≤ 200).
        var match = ItemTestMatches.Build(OneVsOne, 6000);
        Placement.Place(match.World.Balls[0], new Vector2(-1100f, 400f));
        Placement.Place(match.World.Fish[0], new Vector2(-1400f, 100f), 0f);
        match.JudgeCycles(50);
        Assert.Empty(match.EventsOf("foul"));
        match.JudgeCycle();
        var foul = Assert.Single(match.EventsOf("foul"));
        Assert.Equal((51, 0, 0), (foul.Cycle, foul.Team, foul.Fish));
        Assert.Single(match.EventsOf("sent-off"));
        var f = match.World.Fish[0];
        Assert.True(f.OutOfPlay);
        Assert.Equal(new Vector2(-90f, -1080f), f.Position); // x = −1·(2·W), z = top − L/2
        Assert.Equal(MathF.PI / 2f, f.Heading, 5);

        // 8 s off in 1v1, then back in play just inside the wall.
        match.JudgeCycles(79);
        Assert.True(f.OutOfPlay);
        match.JudgeCycle();
        Assert.False(f.OutOfPlay);
        Assert.True(f.Position.Y > -1000f);
    }

    [Fact]
    public void TheGoalFoulNeedsTheBallInTheZone()
    {
        var match = ItemTestMatches.Build(OneVsOne, 6000);
        Placement.Place(match.World.Balls[0], new Vector2(-900f, 0f)); // outside the zone (x > −1008)
        Placement.Place(match.World.Fish[0], new Vector2(-1400f, 100f), 0f);
        match.JudgeCycles(200);
        Assert.Empty(match.EventsOf("foul"));
    }

    [Fact]
    public void TheThirdFishInTheForbiddenZoneTheLastToEnterIsSentOff()
    {
        // 3v3: team 0's three fish in its zone (x ≤ −950, |z| ≤ 500); fish 2 enters 5 cycles after the others.
        var match = ItemTestMatches.Build(ThreeVsThree, 6000);
        var w = match.World;
        Placement.Place(w.Balls[0], new Vector2(-1400f, 400f));
        Placement.Place(w.Fish[0], new Vector2(-1100f, 0f), 0f);
        Placement.Place(w.Fish[1], new Vector2(-1100f, 250f), 0f);
        Placement.Place(w.Fish[2], new Vector2(-800f, -250f), 0f);
        match.JudgeCycles(5);
        Placement.Place(w.Fish[2], new Vector2(-1100f, -250f), 0f);
        match.JudgeCycles(50);
        Assert.Empty(match.EventsOf("foul"));
        match.JudgeCycle();
        var foul = Assert.Single(match.EventsOf("foul"));
        Assert.Equal((56, 2), (foul.Cycle, foul.Fish));
        Assert.True(w.Fish[2].OutOfPlay);
        match.JudgeCycles(99);
        Assert.True(w.Fish[2].OutOfPlay);
        match.JudgeCycle();
        Assert.False(w.Fish[2].OutOfPlay); // 10 s in 3v3
    }

    [Fact]
    public void TwoFishInTheForbiddenZoneAreAllowedIn3V3AndOneFishIn1V1()
    {
        var match = ItemTestMatches.Build(ThreeVsThree, 6000);
        var w = match.World;
        Placement.Place(w.Balls[0], new Vector2(-1400f, 400f));
        Placement.Place(w.Fish[2], new Vector2(-800f, -250f), 0f);
        match.JudgeCycles(300);
        Assert.Empty(match.EventsOf("foul"));
    }

    [Fact]
    public void AFiveVFiveDefenderLeavingItsHalfIsSentOffAtOnce()
    {
        var match = ItemTestMatches.Build(FiveVsFive, 6000);
        var w = match.World;
        match.JudgeCycle();
        Assert.Empty(match.EventsOf("foul")); // the forwards start in their own half: not yet in their area, no foul
        Placement.Place(w.Fish[1], new Vector2(201f, 300f), 0f); // defender of the left team past x = 200
        match.JudgeCycle();
        var foul = Assert.Single(match.EventsOf("foul"));
        Assert.Equal(1, foul.Fish);
        Assert.True(w.Fish[1].OutOfPlay);
        Assert.True(w.Fish[1].Position.Y < -1500f); // parked beyond the top wall (left team)
    }

    [Fact]
    public void AFiveVFiveForwardIsHeldToTheOtherHalfOnceItGotThere()
    {
        var match = ItemTestMatches.Build(FiveVsFive, 6000);
        var w = match.World;
        Placement.Place(w.Fish[3], new Vector2(400f, 300f), 0f); // into the half it attacks
        match.JudgeCycle();
        Assert.Empty(match.EventsOf("foul"));
        Placement.Place(w.Fish[3], new Vector2(-201f, 300f), 0f);
        match.JudgeCycle();
        Assert.Equal(3, Assert.Single(match.EventsOf("foul")).Fish);
    }

    [Fact]
    public void ABallHeldInACornerByBothTeamsForTenSecondsIsADeadBall()
    {
        var match = ItemTestMatches.Build(OneVsOne, 6000);
        Placement.Place(match.World.Balls[0], new Vector2(1300f, -920f)); // corner: |x| ≥ 1242, |z| ≥ 892
        var both = new[] { Judging.Touch(0, 0), Judging.Touch(1, 0) };
        match.JudgeCycles(99, both);
        Assert.Empty(match.EventsOf("dead-ball"));
        match.JudgeCycle(Judging.Touch(0, 0)); // one team only: the count starts again
        match.JudgeCycles(99, both);
        Assert.Empty(match.EventsOf("dead-ball"));
        match.JudgeCycle(both);
        Assert.Equal(200, Assert.Single(match.EventsOf("dead-ball")).Cycle);
        Assert.Equal(new Vector2(750f, -500f), match.World.Balls[0].Position);

        // The fish beside the spot: left team at x − (L + r), right team at x + (L + r), z = spot + 3W(j − 1).
        Assert.Equal(new Vector2(750f - 218f, -500f - 135f), match.World.Fish[0].Position);
        Assert.Equal(new Vector2(750f + 218f, -500f - 135f), match.World.Fish[1].Position);
    }

    [Fact]
    public void ATieGoesToExtraTimeThenPenaltiesThenTheClutchShot()
    {
        var match = ItemTestMatches.Build(OneVsOne, 600);
        var r = (PoloReferee)match.Referee!;
        Assert.Equal("0", r.Variables["CompetitionPeriod"]);
        match.JudgeCycles(600);
        Assert.Equal(PoloPeriod.ExtraTime, r.Period);
        Assert.Equal("1", r.Variables["CompetitionPeriod"]);
        Assert.False(match.IsOver);
        match.JudgeCycles(1800);
        Assert.Equal(PoloPeriod.PenaltyKickTime, r.Period);
        Assert.Equal(0, r.Kicker);

        // The first kick: ball on team 0's penalty spot in front of the right goal (x = 1500 − 150 − 400).
        Assert.Equal(new Vector2(950f, 0f), match.World.Balls[0].Position);
        Assert.Equal(new Vector2(950f - 176f, 0f), match.World.Fish[0].Position);
        Assert.Equal(new Vector2(1500f - 288f, 0f), match.World.Fish[1].Position);
        match.JudgeCycles(10 * PoloReferee.KickCycles);
        Assert.Equal(PoloPeriod.ClutchShotTime, r.Period);
        Assert.Equal("3", r.Variables["CompetitionPeriod"]);
        Assert.Equal(10, match.EventsOf("penalty").Count);

        // The first goal of the clutch shot wins.
        Placement.Place(match.World.Balls[0], new Vector2(-1420f, 0f));
        match.JudgeCycle();
        Assert.True(match.IsOver);
        Assert.Equal(new MatchOutcome(1, "clutch shot (first goal)"), r.Outcome);
    }

    [Fact]
    public void APenaltyScoredAndMissedDecidesAfterTheRound()
    {
        var match = ItemTestMatches.Build(OneVsOne, 600);
        var r = (PoloReferee)match.Referee!;
        match.JudgeCycles(600 + 1800);
        Placement.Place(match.World.Balls[0], new Vector2(1420f, 0f)); // team 0 scores its kick
        match.JudgeCycle();
        Assert.Equal(1, r.Kicker);
        Assert.False(match.IsOver);
        match.JudgeCycles(PoloReferee.KickCycles); // team 1 misses
        Assert.True(match.IsOver);
        Assert.Equal(new MatchOutcome(0, "penalties"), r.Outcome);
    }

    [Fact]
    public void ScoresThatDifferAtFullTimeEndTheMatch()
    {
        var match = ItemTestMatches.Build(OneVsOne, 600);
        Placement.Place(match.World.Balls[0], new Vector2(1420f, 0f));
        match.JudgeCycle();
        match.JudgeCycles(599);
        Assert.True(match.IsOver);
        Assert.Equal(600, match.World.Cycle);
        Assert.Equal(new MatchOutcome(0, "higher score"), match.Referee!.Outcome);
    }

    // Demo against demo, a 1v1 match has a goal in about half of the seeds (seeds 1-24: 13; seeds
    // 1-12: 6), the two demos often blocking
    // each other; which seeds score changes with rounding-sized changes of the motion. No promise
    // names this, so it is checked as a rate: at least 3 of seeds 1-12 (at a rate of one half, 12
    // seeds fall below that about once in 50).
    [Fact]
    public void TheDemosScoreAgainstEachOtherInSomeOfTwelveSeeds()
    {
        var scored = new System.Collections.Generic.List<ulong>();
        for (ulong seed = 1; seed <= 12; seed++)
        {
            var match = ItemTestMatches.Build(OneVsOne, 6000, "demo", seed, noise: true);
            match.PlayAll();
            if (match.Referee!.Scores.Sum() > 0)
            {
                scored.Add(seed);
            }
        }

        Assert.True(scored.Count >= 3, $"goals in ten minutes at seeds {string.Join(", ", scored)} only");
    }

    [Theory]
    [InlineData(1UL)]
    [InlineData(2UL)]
    [InlineData(3UL)]
    public void TheDemoScoresAgainstAnIdleOpponent(ulong seed)
    {
        var match = ItemTestMatches.Build(OneVsOne, 6000, "demo", seed, noise: true,
            edit: s => s with { Fish = s.Fish.Select(f => f.Team == 1 ? f with { Strategy = "idle" } : f).ToList() });
        match.PlayAll();
        Assert.True(match.Referee!.Scores[0] > 0, $"seed {seed}: the demo scored no goal against an idle opponent in ten minutes");
    }

    [Fact]
    public void TheSameSeedPlaysTheSameMatch()
    {
        int[] Play(ulong seed)
        {
            var m = ItemTestMatches.Build(ThreeVsThree, 1200, "demo", seed, noise: true);
            m.PlayAll();
            return [.. m.Referee!.Scores, m.World.Cycle, m.Referee.Events.Count, (int)m.World.Balls[0].Position.X];
        }

        Assert.Equal(Play(5), Play(5));
    }
}
