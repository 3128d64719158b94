using URWPGSim2D.Engine.Items.DoubleFishRace;

namespace URWPGSim2D.Server.Tests.Items;

/// <summary>
/// 双鱼竞速 against the numbers of the original's <c>DoubleFishRaceViaHoles</c>: the layout, the
/// position angle and quadrants, the fouls and where they put the fish back, the angle swum, the
/// level ending and the winner.
/// </summary>
public sealed class DoubleFishRaceTests() : ItemTests(new DoubleFishRaceItem())
{
    [Fact]
    public void TheLayoutIsTheOriginals()
    {
        var s = Item.CreateScenario(1);
        Assert.Equal((3000f, 2000f, false), (s.FieldLength, s.FieldWidth, s.GoalBlocks));
        Assert.Equal(new[] { (0, new Vector2(-1180f, 0f), -MathF.PI / 2f), (1, new Vector2(1180f, 0f), MathF.PI / 2f) }, s.Fish.Select(f => (f.Team, f.Position, f.Heading)).ToArray());
        Assert.Empty(s.Balls);

        // h = 2000 - 6 * 45 = 1730; side walls at -1500 + 225 + 400.
        (float X, float Z, float Length, float Width)[] original = [(-875, 0, 150, 865), (0, 0, 150, 1730), (875, 0, 150, 865)];
        Assert.Equal(original, s.Obstacles.Select(o => (o.Center.X, o.Center.Y, o.Length, o.Width)).ToArray());
        Assert.Equal(("双鱼竞速", 2, 1), (Item.ChineseName, Item.TeamCount, Item.FishPerTeam));
    }

    [Theory]
    [InlineData(100f, 0f, 0f, 1)]
    [InlineData(100f, 100f, 0.7853982f, 1)]
    [InlineData(0f, 100f, 1.5707964f, 2)]
    [InlineData(-100f, 100f, 2.3561945f, 2)]
    [InlineData(-100f, 0f, 3.1415927f, 3)]
    [InlineData(-100f, -100f, 3.926991f, 3)]
    [InlineData(0f, -100f, 1.5707964f, 4)] // the original's own value on the -z axis (3π/2, then 2π less it)
    [InlineData(100f, -100f, 5.497787f, 4)]
    public void ThePositionAngleGrowsFromPlusXTowardPlusZ(float x, float z, float angle, int quadrant)
    {
        var (a, q) = DoubleFishRaceReferee.Place(new Vector2(x, z));
        Assert.Equal(angle, a, 5);
        Assert.Equal(quadrant, q);
    }

    [Fact]
    public void PutBackPlacesFollowTheOriginalsFormulas()
    {
        // Beside the side walls (875 + 75 + 50) or beyond the centre wall's ends (865 + 50).
        Assert.Equal((new Vector2(1000f, 0f), MathF.PI / 2f), DoubleFishRaceReferee.Restart(1));
        Assert.Equal((new Vector2(0f, 915f), MathF.PI), DoubleFishRaceReferee.Restart(2));
        Assert.Equal((new Vector2(-1000f, 0f), 3f * MathF.PI / 2f), DoubleFishRaceReferee.Restart(3));
        Assert.Equal((new Vector2(0f, -915f), 0f), DoubleFishRaceReferee.Restart(4));
    }

    [Fact]
    public void TheAngleSwumAddsUpAcrossTheQuadrantFourWrap()
    {
        var match = ItemTestMatches.Build(Item, 6000);
        var r = (DoubleFishRaceReferee)match.Referee!;
        var w = match.World;

        // Team 1's fish round from angle 0 through quadrants 1, 2, 3, 4 and back into 1: one lap.
        Vector2[] way = [new(1200f, 700f), new(-1200f, 700f), new(-1200f, -700f), new(1200f, -700f), new(1200f, 10f)];
        Placement.Place(w.Fish[0], new Vector2(-1200f, -10f), 0f);
        foreach (var p in way)
        {
            Placement.Place(w.Fish[1], p, 0f);
            match.JudgeCycle();
        }

        Assert.Equal(2 * Math.PI + Math.Atan2(10, 1200), r.Swum(1), 4);
        Assert.Equal(360, r.Scores[1]);
        Assert.Empty(match.EventsOf("foul"));
    }

    [Fact]
    public void GoingBackAQuadrantIsAFoulAndPutsTheFishBack()
    {
        var match = ItemTestMatches.Build(Item, 6000);
        var r = (DoubleFishRaceReferee)match.Referee!;
        var w = match.World;

        // Team 0's fish starts in quadrant 3; back into quadrant 2 is a foul: put back at (-1000, 0).
        Placement.Place(w.Fish[0], new Vector2(-1200f, 300f), 0f);
        match.JudgeCycle();
        Assert.Equal(new Vector2(-1000f, 0f), w.Fish[0].Position);
        Assert.Equal(0, r.Swum(0));
        var foul = Assert.Single(match.EventsOf("foul"));
        Assert.Equal((0, 0), (foul.Team, foul.Fish));

        // Two quadrants at once (3 to 1) is a foul too; on an axis never.
        Placement.Place(w.Fish[0], new Vector2(-1200f, 0f), 0f);
        match.JudgeCycle();
        Placement.Place(w.Fish[0], new Vector2(1200f, 300f), 0f);
        match.JudgeCycle();
        Assert.Equal(2, match.EventsOf("foul").Count);
    }

    [Fact]
    public void CrossingTheMiddleLineBetweenTheSideWallsIsAFoul()
    {
        var match = ItemTestMatches.Build(Item, 6000);
        var w = match.World;
        Placement.Place(w.Fish[1], new Vector2(1200f, 700f), 0f);

        // Team 0's fish forward into quadrant 4, then across z = 0 at x = 800 (the right wall's face): a foul.
        Vector2[] way = [new(-1200f, -700f), new(1200f, -700f), new(800f, -5f), new(800f, 5f)];
        foreach (var p in way)
        {
            Placement.Place(w.Fish[0], p, 0f);
            match.JudgeCycle();
        }

        var foul = Assert.Single(match.EventsOf("foul"));
        Assert.Equal(0, foul.Team);
        Assert.Equal(new Vector2(0f, -915f), w.Fish[0].Position);

        // Outside the walls (x > 800) the crossing is the way round.
        Placement.Place(w.Fish[0], new Vector2(1200f, -5f), 0f);
        match.JudgeCycle();
        Placement.Place(w.Fish[0], new Vector2(1200f, 5f), 0f);
        match.JudgeCycle();
        Assert.Single(match.EventsOf("foul"));
    }

    [Fact]
    public void LevelFishEndTheMatchAndTheLargerAngleWins()
    {
        var match = ItemTestMatches.Build(Item, 6000);
        var r = (DoubleFishRaceReferee)match.Referee!;
        var w = match.World;

        // Team 0's fish moves up the left side, team 1's stays; then team 0's comes within 2 degrees of team 1's.
        Placement.Place(w.Fish[0], new Vector2(-1200f, -700f), 0f);
        Placement.Place(w.Fish[1], new Vector2(1200f, 700f), 0f);
        match.JudgeCycle();
        Placement.Place(w.Fish[0], new Vector2(1200f, -700f), 0f);
        match.JudgeCycle();
        Assert.False(match.IsOver);
        Placement.Place(w.Fish[0], new Vector2(1200f, 0.01f), 0f);
        Placement.Place(w.Fish[1], new Vector2(1200f, 40f), 0f);
        match.JudgeCycle();
        Assert.True(match.IsOver);
        Assert.Equal(0, r.Outcome.Winner);
        Assert.StartsWith("larger angle swum, ", r.Outcome.Rule, StringComparison.Ordinal);
        Assert.Equal(new[] { "level", "end" }, r.Events.Select(e => e.Kind).ToArray());
    }

    [Fact]
    public void TheDemoFishLapWithoutFouls()
    {
        var match = ItemTestMatches.Build(Item, 1500, "demo", 1, noise: true);
        match.PlayAll();
        var r = (DoubleFishRaceReferee)match.Referee!;
        Assert.True(r.Swum(0) > 2 * Math.PI && r.Swum(1) > 2 * Math.PI, $"swum {r.Swum(0)} and {r.Swum(1)} rad");
        Assert.Empty(match.EventsOf("foul"));
    }
}
