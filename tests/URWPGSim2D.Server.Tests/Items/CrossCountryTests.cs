using URWPGSim2D.Engine.Items.CrossCountry;

namespace URWPGSim2D.Server.Tests.Items;

/// <summary>障碍越野: the four steps in order, the 22 mm target, the end.</summary>
public sealed class CrossCountryTests() : ItemTests(new CrossCountryItem())
{
    [Fact]
    public void TheStepsCountOnlyInOrder()
    {
        var match = ItemTestMatches.Build(Item, 6000);
        var r = (CrossCountryReferee)match.Referee!;
        var w = match.World;

        // Ball 0 on its target before the fish touched it: nothing.
        Placement.Place(w.Balls[0], CrossCountryLayout.Targets[0]);
        match.JudgeCycle();
        Assert.Equal(0, r.Step);

        // Touching ball 1 first does not count either.
        match.JudgeCycle(Judging.Touch(0, 1));
        Assert.Equal(0, r.Step);

        match.JudgeCycle(Judging.Touch(0, 0));
        Assert.Equal((1, 3), (r.Step, r.StepCycle(1)));
        match.JudgeCycle();
        Assert.Equal((2, 4), (r.Step, r.StepCycle(2)));
        Assert.Equal(1, r.Scores[0]);

        // Ball 1: touch, then within 22 mm of (1900, 1200).
        Placement.Place(w.Balls[1], CrossCountryLayout.Targets[1] + new Vector2(0f, 23f));
        match.JudgeCycle(Judging.Touch(0, 1));
        match.JudgeCycle();
        Assert.Equal(3, r.Step);
        Placement.Place(w.Balls[1], CrossCountryLayout.Targets[1] + new Vector2(21f, 0f));
        match.JudgeCycle();
        Assert.Equal(4, r.Step);
        Assert.True(match.IsOver);
        Assert.Equal(new MatchOutcome(0, "course completed in 0.7 s"), r.Outcome);
        Assert.Equal(new[] { "touch", "target", "touch", "target", "end" }, System.Linq.Enumerable.ToArray(System.Linq.Enumerable.Select(r.Events, e => e.Kind)));
    }

    [Fact]
    public void OneStepPerCycle()
    {
        // Touching ball 0 while it already lies on its target: the target step follows a cycle later.
        var match = ItemTestMatches.Build(Item, 6000);
        var r = (CrossCountryReferee)match.Referee!;
        Placement.Place(match.World.Balls[0], CrossCountryLayout.Targets[0]);
        match.JudgeCycle(Judging.Touch(0, 0));
        Assert.Equal(1, r.Step);
        match.JudgeCycle();
        Assert.Equal(2, r.Step);
    }

    [Fact]
    public void TimeUpWithoutTheCourseIsNoWin()
    {
        var match = ItemTestMatches.Build(Item, 50);
        match.JudgeCycle(Judging.Touch(0, 0));
        match.JudgeCycles(49);
        Assert.True(match.IsOver);
        Assert.Equal(new MatchOutcome(-1, "course not completed (1 of 4 steps)"), match.Referee!.Outcome);
    }

    [Fact]
    public void TheDemoTouchesTheFirstBall()
    {
        var match = ItemTestMatches.Build(Item, 1200, "demo", 1, noise: true);
        match.PlayAll();
        Assert.True(((CrossCountryReferee)match.Referee!).Step >= 1, "the demo fish never touched ball 0 in two minutes");
    }
}
