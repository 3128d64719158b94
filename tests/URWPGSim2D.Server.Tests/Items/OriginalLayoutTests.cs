using URWPGSim2D.Engine.Items.CrossCountry;
using URWPGSim2D.Engine.Items.Polo;
using URWPGSim2D.Engine.Items.Rescue;
using URWPGSim2D.Engine.Items.Snooker;

namespace URWPGSim2D.Server.Tests.Items;

/// <summary>
/// The layouts of rescue, cross-country, water polo and snooker against the numbers written in the
/// original's Match/ sources (QuickRescue.cs, ObstacleRacing.cs, Match1V1/3V3/5V5.cs,
/// MatchSnooker.cs), copied here by hand as literals.
/// </summary>
public sealed class OriginalLayoutTests
{
    [Fact]
    public void RescueMatchesQuickRescueCs()
    {
        var s = RescueLayout.Scenario();
        Assert.Equal((4500f, 3000f, false), (s.FieldLength, s.FieldWidth, s.GoalBlocks));
        Assert.Equal(new[] { (0f, 0f), (550f, 950f), (-550f, 950f), (550f, -950f), (-550f, -950f) }, s.Obstacles.Select(o => (o.Center.X, o.Center.Y)));
        Assert.All(s.Obstacles, o => Assert.Equal((ObstacleKind.Rectangle, 100f, 1100f, 0f), (o.Kind, o.Length, o.Width, o.Heading)));
        Assert.Equal(new[] { (-1350f, 1050f, 58f), (-1350f, -1050f, 58f) }, s.Balls.Select(b => (b.Position.X, b.Position.Y, b.Radius)));
        Assert.Equal(
            new[] { (0, 1350f, 700f), (0, 1350f, -700f), (1, -1350f, 0f), (1, -2115f, 1591f) },
            s.Fish.Select(f => (f.Team, f.Position.X, f.Position.Y)));
        Assert.Equal(new[] { MathF.PI, MathF.PI, 0f, 0f }, s.Fish.Select(f => f.Heading));

        // Zone x ∈ [1850, 2250], z ∈ [−500, 500], bounds included.
        Assert.True(RescueLayout.InZone(new Vector2(1850f, -500f)));
        Assert.True(RescueLayout.InZone(new Vector2(2250f, 500f)));
        Assert.False(RescueLayout.InZone(new Vector2(1849.9f, 0f)));
        Assert.False(RescueLayout.InZone(new Vector2(2000f, 500.1f)));
    }

    [Fact]
    public void RescueSwapsWhoRescues()
    {
        var second = RescueLayout.Poses(rescuer: 1);
        Assert.Equal(new[] { (-1350f, 0f, 0f), (-2115f, 1591f, 0f), (1350f, 700f, MathF.PI), (1350f, -700f, MathF.PI) },
            second.Select(p => (p.Position.X, p.Position.Y, p.Heading)));
    }

    [Fact]
    public void CrossCountryMatchesObstacleRacingCs()
    {
        var s = CrossCountryLayout.Scenario();
        Assert.Equal((4500f, 3000f, false), (s.FieldLength, s.FieldWidth, s.GoalBlocks));
        var fish = Assert.Single(s.Fish);
        Assert.Equal((0, 1600f, 0f, MathF.PI), (fish.Team, fish.Position.X, fish.Position.Y, fish.Heading));
        Assert.Equal(new[] { (-1600f, -1200f, 58f), (-1600f, 1200f, 58f) }, s.Balls.Select(b => (b.Position.X, b.Position.Y, b.Radius)));
        Assert.Equal(
            new[]
            {
                (ObstacleKind.Round, 0f, 0f, 80f), (ObstacleKind.Round, -1000f, 0f, 80f), (ObstacleKind.Round, 1000f, 0f, 80f),
                (ObstacleKind.Rectangle, 0f, 1350f, 0f), (ObstacleKind.Rectangle, 0f, 1050f, 0f),
                (ObstacleKind.Rectangle, 0f, -1350f, 0f), (ObstacleKind.Rectangle, 0f, -1050f, 0f),
            },
            s.Obstacles.Select(o => (o.Kind, o.Center.X, o.Center.Y, o.Radius)));
        Assert.All(s.Obstacles.Skip(3), o => Assert.Equal((200f, 100f, 0f), (o.Length, o.Width, o.Heading)));
        Assert.Equal(new[] { new Vector2(1900f, -1200f), new Vector2(1900f, 1200f) }, CrossCountryLayout.Targets);
    }

    [Theory]
    [InlineData(21.9f, true)]
    [InlineData(22f, true)]
    [InlineData(22.1f, false)]
    [InlineData(23f, false)]
    public void CrossCountryTargetIsTwentyTwoMillimetres(float distance, bool home)
    {
        // The original: (x − 1900)² + (z + 1200)² ≤ 484.
        var target = CrossCountryLayout.Targets[0];
        var dir = Vector2.Normalize(new Vector2(3f, 4f));
        Assert.Equal(home, CrossCountryLayout.AtTarget(target + (dir * distance), target));
    }

    [Fact]
    public void Polo1V1MatchesMatch1V1Cs()
    {
        // f.LeftMm + BodyLength · 3 = −1500 + 480; the right fish mirrors it, facing π.
        var s = PoloLayout.Scenario(1);
        Assert.Equal((3000f, 2000f, true), (s.FieldLength, s.FieldWidth, s.GoalBlocks));
        Assert.Equal(new[] { (0, -1020f, 0f, 0f), (1, 1020f, 0f, MathF.PI) }, s.Fish.Select(f => (f.Team, f.Position.X, f.Position.Y, f.Heading)));
        var ball = Assert.Single(s.Balls);
        Assert.Equal((0f, 0f, 58f), (ball.Position.X, ball.Position.Y, ball.Radius));
        Assert.Empty(s.Obstacles);
    }

    [Fact]
    public void Polo3V3MatchesMatch3V3Cs()
    {
        // Fish 1 and 2 at z = ±BodyWidth · 3 = ±135 on both sides.
        var s = PoloLayout.Scenario(3);
        Assert.Equal((3000f, 2000f), (s.FieldLength, s.FieldWidth));
        Assert.Equal(
            new[] { (0, -1020f, 0f), (0, -1020f, 135f), (0, -1020f, -135f), (1, 1020f, 0f), (1, 1020f, 135f), (1, 1020f, -135f) },
            s.Fish.Select(f => (f.Team, f.Position.X, f.Position.Y)));
    }

    [Fact]
    public void Polo5V5MatchesMatch5V5Cs()
    {
        // 4500 × 3000; backs at ∓(2250 − 480); forwards at ∓2L = ∓320, z = ±2W (kick-off side) or ±10W.
        var s = PoloLayout.Scenario(5);
        Assert.Equal((4500f, 3000f, true), (s.FieldLength, s.FieldWidth, s.GoalBlocks));
        Assert.Equal(
            new[]
            {
                (0, -1770f, 0f), (0, -1770f, 135f), (0, -1770f, -135f), (0, -320f, 90f), (0, -320f, -90f),
                (1, 1770f, 0f), (1, 1770f, 135f), (1, 1770f, -135f), (1, 320f, 450f), (1, 320f, -450f),
            },
            s.Fish.Select(f => (f.Team, f.Position.X, f.Position.Y)));

        // After the left team scores the right team kicks off: its forwards at ±2W, the left ones at ±10W.
        var left = PoloLayout.KickOffPoses(5, leftSide: true, kicksOff: false, FishSize.Default);
        var right = PoloLayout.KickOffPoses(5, leftSide: false, kicksOff: true, FishSize.Default);
        Assert.Equal((-320f, 450f), (left[3].Position.X, left[3].Position.Y));
        Assert.Equal((320f, -90f), (right[4].Position.X, right[4].Position.Y));
    }

    [Fact]
    public void PoloZonesMatchTheOriginalsFieldConstants()
    {
        // GoalDepth 150, GoalWidth 400, ForbiddenZone 400 × 1000; ball wholly inside: x ≤ −1500 + 150 − 58 = −1408, |z| ≤ 142.
        Assert.True(PoloLayout.BallInGoal(new Vector2(-1408f, 142f), 58f, 3000f, -1));
        Assert.False(PoloLayout.BallInGoal(new Vector2(-1407f, 0f), 58f, 3000f, -1));
        Assert.False(PoloLayout.BallInGoal(new Vector2(-1450f, 143f), 58f, 3000f, -1));
        Assert.True(PoloLayout.BallInGoal(new Vector2(2158f, 0f), 58f, 4500f, 1));

        // Forbidden zone for the ball: x ≤ −1500 + 550 − 58 = −1008, |z| ≤ 442; for a fish: x ≤ −950, |z| ≤ 500.
        Assert.True(PoloLayout.BallInForbiddenZone(new Vector2(-1008f, 442f), 58f, 3000f, -1));
        Assert.False(PoloLayout.BallInForbiddenZone(new Vector2(-1007f, 0f), 58f, 3000f, -1));
        Assert.True(PoloLayout.FishInForbiddenZone(new Vector2(950f, -500f), 3000f, 1));
        Assert.False(PoloLayout.FishInForbiddenZone(new Vector2(949f, 0f), 3000f, 1));
        Assert.True(PoloLayout.FishInGoal(new Vector2(-1350f, 200f), 3000f, -1));
        Assert.False(PoloLayout.FishInGoal(new Vector2(-1349f, 0f), 3000f, -1));

        // Dead-ball corners: |x| ≥ 1500 − 258, |z| ≥ 1000 − 108; free-ball spots (±750, ±500) and (±1125, ±750).
        Assert.True(PoloLayout.BallInCorner(new Vector2(1242f, -892f), 58f, 3000f, 2000f));
        Assert.False(PoloLayout.BallInCorner(new Vector2(1241f, -950f), 58f, 3000f, 2000f));
        Assert.Equal(new Vector2(750f, -500f), PoloLayout.FreeBallSpot(new Vector2(1300f, -900f), 3000f, 2000f));
        Assert.Equal(new Vector2(-1125f, 750f), PoloLayout.FreeBallSpot(new Vector2(-2000f, 1400f), 4500f, 3000f));
        Assert.Equal(new Vector2(-950f, 0f), PoloLayout.PenaltySpot(3000f, -1));
    }

    [Fact]
    public void SnookerMatchesMatchSnookerCs()
    {
        var s = SnookerLayout.Scenario();
        Assert.Equal((4500f, 3000f, false), (s.FieldLength, s.FieldWidth, s.GoalBlocks));
        var fish = Assert.Single(s.Fish);
        Assert.Equal((-1104f, 0f, 0f), (fish.Position.X, fish.Position.Y, fish.Heading)); // −6 · 184

        // Cushions (4500 − 3 · 150) / 2 = 2025 long, 150 wide, at x = ±(2025 + 150) / 2, z = ∓1500 ± 75.
        Assert.Equal(new[] { (-1087.5f, -1425f), (1087.5f, -1425f), (-1087.5f, 1425f), (1087.5f, 1425f) }, s.Obstacles.Select(o => (o.Center.X, o.Center.Y)));
        Assert.All(s.Obstacles, o => Assert.Equal((ObstacleKind.Rectangle, 2025f, 150f, 0f), (o.Kind, o.Length, o.Width, o.Heading)));

        // Reds from 2R = 368 in rows 58·√3 apart; colours at −2R, −4R, (−6R, ∓2R).
        float s3 = 58f * MathF.Sqrt(3f);
        var expected = new[]
        {
            (368f, 0f), (368f + s3, 58f), (368f + s3, -58f), (368f + (2f * s3), 116f), (368f + (2f * s3), 0f), (368f + (2f * s3), -116f),
            (-368f, 0f), (-736f, 0f), (-1104f, -368f), (-1104f, 368f),
        };
        Assert.Equal(expected, s.Balls.Select(b => (b.Position.X, b.Position.Y)));
        Assert.All(s.Balls, b => Assert.Equal(58f, b.Radius));
        Assert.Equal(new[] { 1, 1, 1, 1, 1, 1, 2, 3, 4, 5 }, Enumerable.Range(0, 10).Select(SnookerLayout.Value));
    }

    [Theory]
    [InlineData(-2175f, -1408f, -1)] // top left corner: −2192 < x < −2158, z ≤ −1408
    [InlineData(-2192f, -1450f, 0)] // the left corner's bounds are open
    [InlineData(17f, -1420f, -1)] // middle: |x| ≤ 17
    [InlineData(18f, -1420f, 0)]
    [InlineData(2192f, 1408f, 1)] // right corner bounds closed, bottom row z ≥ 1408
    [InlineData(2175f, -1407f, 0)] // not deep enough
    [InlineData(1000f, -1440f, 0)] // under a cushion's x range
    public void SnookerPocketsAreTheOriginalsRanges(float x, float z, int pocket)
    {
        Assert.Equal(pocket, SnookerLayout.Pocket(new Vector2(x, z)));
    }
}
