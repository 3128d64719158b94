namespace URWPGSim2D.Server.Tests.Simulation;

/// <summary>
/// Bodies pressed together for a long time settle and stay: a fish swimming at full speed pushes a
/// ball, or a row of touching balls, into the pool's wall (away from the goal mouth) and keeps
/// pushing for hundreds of cycles. Once pressed, no ball creeps along what holds it (a
/// head-on push has no sideways part) or moves at all, no pair sinks into another or into the wall
/// by more than 1 mm (the audit checks every pair by brute force), and the fish never gets past
/// the ball it presses.
/// </summary>
public sealed class PressedBodiesTests
{
    [Theory]
    [InlineData(1)]
    [InlineData(2)]
    [InlineData(3)]
    public void BallsPressedByAFishIntoTheWallSettleAndStay(int balls)
    {
        // The right wall is at x = 1,500; the balls roll at z = 600, clear of the goal mouth.
        const int z = 600;
        var parts = new System.Text.StringBuilder();
        for (int i = 0; i < balls; i++)
        {
            parts.Append(i == 0 ? string.Empty : ",").Append(System.FormattableString.Invariant($"{{\"position\":[{1000 + (i * 118)},{z}]}}"));
        }

        var match = TestMatches.FromJson($$$"""{"field":{"length":3000,"width":2000,"goalBlocks":false},"fish":[{"team":0,"position":[600,{{{z}}}],"heading":0,"decision":{"vcode":14,"tcode":7}}],"balls":[{{{parts}}}]}""");
        var fish = match.World.Fish[0];
        var ball = match.World.Balls;
        float radius = ball[0].Radius;
        var settled = new System.Numerics.Vector2[balls];
        for (int k = 1; k <= 400; k++)
        {
            match.Step();
            float deepest = OverlapAudit.DeepestOverlap(match.World, out string where);
            Assert.True(deepest <= 1f, $"cycle {k}: {where} overlaps {deepest} mm");
            Assert.True(fish.Position.X + fish.HeadReach <= ball[0].Position.X - radius + 1f, $"cycle {k}: the fish's head at {fish.Position.X + fish.HeadReach}, the ball's back at {ball[0].Position.X - radius}");
            if (k == 200)
            {
                // By now the fish has pushed the row to the wall: the last ball touches it.
                Assert.True(MathF.Abs(ball[balls - 1].Position.X - (1500f - radius)) <= 1f, $"cycle {k}: the last ball at {ball[balls - 1].Position}");
                for (int i = 0; i < balls; i++)
                {
                    settled[i] = ball[i].Position;
                }
            }
            else if (k > 200)
            {
                for (int i = 0; i < balls; i++)
                {
                    float moved = System.Numerics.Vector2.Distance(ball[i].Position, settled[i]);
                    Assert.True(moved <= 1f, $"cycle {k}: ball {i} moved {moved} mm since cycle 200 ({ball[i].Position})");
                    Assert.True(MathF.Abs(ball[i].Position.Y - z) <= 0.5f, $"cycle {k}: ball {i} crept sideways to z = {ball[i].Position.Y}");
                }
            }
        }
    }
}
