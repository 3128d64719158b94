namespace URWPGSim2D.Server.Tests.Simulation;

/// <summary>A ball at 5,000 mm/s (500 mm per cycle) passes through nothing.</summary>
public sealed class TunnellingTests
{
    private const float Fast = 5000f;

    [Fact]
    public void NotThroughAWall()
    {
        // From 100 mm below the top wall's contact line, heading into it at 500 mm per cycle.
        var match = TestMatches.Balls(string.Empty, 0f, -840f, 0f, -Fast);
        match.Step();
        Assert.InRange(match.BallAt(0).Y, -1000f + 58f - 0.5f, -800f);
        Assert.Contains(match.Contacts.Cycle.ToArray(), c => c.Pair.Kind == PairKind.BallWall);
    }

    [Fact]
    public void NotThroughAGoalBlock()
    {
        // Toward the right upper goal block (x ≥ 1350, z ≤ −200) along z = −600.
        var match = TestMatches.Balls(string.Empty, 1000f, -600f, Fast, 0f);
        match.Step();
        Assert.InRange(match.BallAt(0).X, 1000f, 1350f - 58f + 0.5f);
        Assert.Contains(match.Contacts.Cycle.ToArray(), c => c.Pair.Kind == PairKind.BallStatic);
    }

    [Theory]
    [InlineData(0f)]
    [InlineData(0.3f)]
    public void NotThroughAThinObstacle(float heading)
    {
        // A 20 mm thick wall-like rectangle across the path at x = 200, the ball 250 mm before it.
        string obstacle = System.FormattableString.Invariant($",\"obstacles\":[{{\"type\":\"rectangle\",\"center\":[200,0],\"length\":20,\"width\":600,\"heading\":{heading}}}]");
        var match = TestMatches.Balls(obstacle, -50f, 0f, Fast, 0f);
        match.Play(3);
        Assert.True(match.BallAt(0).X < 200f, $"ball at {match.BallAt(0)}");
        Assert.True(match.Statistics.LargestLeftoverOverlap <= 1f);
    }

    [Fact]
    public void NotThroughAnotherBall()
    {
        var match = TestMatches.Balls(string.Empty, -400f, 0f, Fast, 0f, 0f, 0f, 0f, 0f);
        match.Step();
        Assert.True(match.BallAt(0).X < match.BallAt(1).X, $"A {match.BallAt(0)} B {match.BallAt(1)}");
        Assert.Contains(match.Contacts.Cycle.ToArray(), c => c.Pair.Kind == PairKind.BallBall);
    }

    [Fact]
    public void NotThroughAFishTail()
    {
        // A still fish heading +X at x = 300: tail segment 3 spans x ≈ 14…69 mm (about 10–13 mm wide).
        // The ball crosses the line z = 0 at x = 40 moving +Z at 500 mm per cycle.
        var match = TestMatches.FromJson("""
            {"fish":[{"team":0,"position":[300,0],"strategy":"idle"}],
             "balls":[{"position":[40,-250],"velocity":[0,5000],"radius":58}]}
            """);
        // The light tail is swatted aside (the fish spins), but the ball must stay on the side of the
        // tail it came from: left of the tail's axis (the body axis, joints are 0 for an idle fish).
        match.Step();
        var contacts = match.Contacts.Cycle.ToArray();
        Assert.Contains(contacts, c => c.Pair.Kind == PairKind.FishBall && c.PartA is (sbyte)FishPart.Tail3 or (sbyte)FishPart.Tail2 or (sbyte)FishPart.LeftCaudal);
        var fish = match.World.Fish[0];
        var tail = new FishModel(fish.Size, fish.Pose).GetLeaf(FishPart.Tail3);
        Vector2 middle = (tail[0] + tail[1] + tail[2] + tail[3]) / 4f;
        Vector2 u = fish.Forward;
        Vector2 ball = match.BallAt(0);
        Assert.True((u.X * (ball.Y - middle.Y)) - (u.Y * (ball.X - middle.X)) < 0f, $"ball at {ball}, tail at {middle}, heading {fish.Heading}");
        Assert.True(match.Motion.LeftoverOverlap <= 1f);
    }
}
