namespace URWPGSim2D.Server.Tests.Simulation;

/// <summary>The motion world finds the analytic time of first contact and resolves the contact there.</summary>
public sealed class TimeOfFirstContactTests
{
    [Theory]
    [InlineData(42f, 1000f)]
    [InlineData(200f, 2500f)]
    [InlineData(437f, 5000f)]
    public void ABallMovingTowardAWallTouchesItAtTheAnalyticTime(float gap, float speed)
    {
        // Ball radius 58 moving +Z toward the wall z = 1000 with `gap` mm to go: contact at gap / (v·0.1 s).
        float z0 = 1000f - 58f - gap;
        var match = TestMatches.Balls(string.Empty, 0f, z0, 0f, speed);
        match.Step();
        var contact = Assert.Single(match.Contacts.Cycle.ToArray());
        Assert.Equal(PairKind.BallWall, contact.Pair.Kind);
        double expected = gap / (speed * 0.1);
        Assert.InRange(contact.Time, expected - (0.3 / (speed * 0.1)), expected + (0.3 / (speed * 0.1)));
        Assert.Equal(0f, contact.Normal.X, 1e-4f);
        Assert.Equal(-1f, contact.Normal.Y, 1e-4f);

        // Restitution 0.001: the ball stays at the wall, moving away at a thousandth of its speed (before drag).
        var ball = match.World.Balls[0];
        Assert.InRange(ball.Position.Y, 1000f - 58f - 0.5f, 1000f - 58f);
        Assert.InRange(ball.Velocity.Y, -0.0011f * speed, 0f);
    }

    [Fact]
    public void TwoBallsMeetAtTheAnalyticTimeAndShareTheMomentum()
    {
        // A at x = −300 moving +X at 2000 mm/s, B at rest at x = 0: the gap 300 − 116 = 184 mm closes at t = 0.92 of the cycle.
        var match = TestMatches.Balls(string.Empty, -300f, 0f, 2000f, 0f, 0f, 0f, 0f, 0f);
        match.Step();
        var contact = Assert.Single(match.Contacts.Cycle.ToArray());
        Assert.Equal(PairKind.BallBall, contact.Pair.Kind);
        Assert.InRange(contact.Time, 0.92 - 0.002, 0.92 + 0.002);

        // Equal masses, e = 0.005: vA' = v(1 − e)/2, vB' = v(1 + e)/2, then one cycle of drag (250 mm/s²).
        float va = (2000f * (1f - 0.005f) / 2f) - 25f;
        float vb = (2000f * (1f + 0.005f) / 2f) - 25f;
        Assert.Equal(va, match.World.Balls[0].Velocity.X, 0.5f);
        Assert.Equal(vb, match.World.Balls[1].Velocity.X, 0.5f);

        // After the contact both travel 0.08 s at their new speeds.
        float contactA = -300f + (2000f * 0.092f);
        Assert.Equal(contactA + (995f * 0.008f), match.BallAt(0).X, 0.5f);
        Assert.Equal(1005f * 0.008f, match.BallAt(1).X, 0.5f);
    }
}
