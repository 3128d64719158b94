using URWPGSim2D.Engine.Items.Snooker;
using URWPGSim2D.Engine.Matches;

namespace URWPGSim2D.Server.Tests.Items;

/// <summary>斯诺克: red then colour, colour values id − 4, wrong pots, the colours in order, BallsInFieldFlag.</summary>
public sealed class SnookerTests() : ItemTests(new SnookerItem())
{
    private static readonly Vector2 MiddleTop = new(0f, -1420f);

    private (Match Match, SnookerReferee Referee) Build()
    {
        var match = ItemTestMatches.Build(Item, 6000);
        return (match, (SnookerReferee)match.Referee!);
    }

    private static void Pot(Match match, int ball)
    {
        Placement.Place(match.World.Balls[ball], MiddleTop);
        match.JudgeCycle();
    }

    [Fact]
    public void ARedThenAColourScoresOneThenIdMinusFour()
    {
        var (match, r) = Build();
        Assert.Equal("1023", r.Variables["BallsInFieldFlag"]);
        Pot(match, 2);
        Assert.Equal(1, r.Scores[0]);
        Assert.True(match.World.Balls[2].OutOfPlay);
        Assert.Equal(0x3FB, r.BallsInField);
        Assert.Equal("1019", r.Variables["BallsInFieldFlag"]);

        Pot(match, 9); // colour 9 scores 5 and is re-spotted while reds remain
        Assert.Equal(6, r.Scores[0]);
        Assert.Equal(SnookerLayout.Spot(9), match.World.Balls[9].Position);
        Assert.False(match.World.Balls[9].OutOfPlay);
        Assert.Equal(new[] { 1.0, 5.0 }, match.EventsOf("ball-in-hole").Select(e => e.Value));
    }

    [Fact]
    public void TheFirstPotMustBeARed()
    {
        var (match, r) = Build();
        Pot(match, 7);
        Assert.Equal(0, r.Scores[0]);
        Assert.Equal(SnookerLayout.Spot(7), match.World.Balls[7].Position);
        Assert.Equal(0.0, Assert.Single(match.EventsOf("ball-in-hole")).Value);
    }

    [Fact]
    public void TwoRedsInARowTheSecondIsWrongAndGoesBackBesideAWall()
    {
        var (match, r) = Build();
        Pot(match, 0);
        Pot(match, 1); // top pocket: back against the right wall at z = 0
        Assert.Equal(1, r.Scores[0]);
        Assert.Equal(new Vector2(2250f - 58f, 0f), match.World.Balls[1].Position);
        Assert.False(match.World.Balls[1].OutOfPlay);
        Assert.Equal(0x3FE, r.BallsInField);

        // The wrong pot still counts as the last pot: a colour is good next.
        Pot(match, 6);
        Assert.Equal(3, r.Scores[0]);
    }

    [Fact]
    public void AfterTheRedsTheColoursGoDownInOrderAndTheMatchEnds()
    {
        var (match, r) = Build();
        for (int red = 0; red < 6; red++)
        {
            Pot(match, red);
            if (red < 5)
            {
                Pot(match, 6); // +2 each time, re-spotted while reds remain
            }
        }

        Assert.Equal(16, r.Scores[0]);
        Assert.Equal(0x3C0, r.BallsInField);
        Pot(match, 8); // not the lowest colour: wrong, re-spotted
        Assert.Equal(16, r.Scores[0]);
        foreach (int colour in new[] { 6, 7, 8, 9 })
        {
            Pot(match, colour);
            Assert.True(match.World.Balls[colour].OutOfPlay);
        }

        Assert.Equal(16 + 2 + 3 + 4 + 5, r.Scores[0]);
        Assert.Equal(0, r.BallsInField);
        Assert.True(match.IsOver);
        Assert.Equal(new MatchOutcome(0, "every ball potted"), r.Outcome);
    }

    [Fact]
    public void OneBallIsJudgedPerCycleLowestIdFirst()
    {
        var (match, r) = Build();
        Placement.Place(match.World.Balls[6], new Vector2(-2175f, -1420f));
        Placement.Place(match.World.Balls[3], new Vector2(2175f, 1420f));
        match.JudgeCycle();
        Assert.Equal(3, Assert.Single(match.EventsOf("ball-in-hole")).Ball);
        match.JudgeCycle();
        Assert.Equal(new[] { 3, 6 }, match.EventsOf("ball-in-hole").Select(e => e.Ball));
        Assert.Equal(3, r.Scores[0]);
    }

    [Fact]
    public void APottedBallIsOutOfPlayAndTheFishSwimsThroughItsPlace()
    {
        var match = ItemTestMatches.Build(Item, 6000);
        Placement.Place(match.World.Balls[0], MiddleTop);
        match.Step();
        var b = match.World.Balls[0];
        Assert.True(b.OutOfPlay);
        Assert.True(b.Position.Y < -1500f);
        var at = b.Position;
        match.Play(20);
        Assert.Equal(at, match.World.Balls[0].Position);
    }
}
