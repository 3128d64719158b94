namespace URWPGSim2D.Collision.Tests.Motion;

/// <summary>
/// The end of a step: the deepest overlap it reports (<see cref="MotionWorld.LeftoverOverlap"/>) is the
/// deepest among the pairs of the bodies that took part in contacts, measured after settling; when
/// settling resolves nothing the first pass's depths are that answer (no second pass). Settling
/// before the first step works (the broad phase is built on demand).
/// </summary>
public sealed class MotionWorldSettleTests
{
    private const float Slop = 0.01f; // overlaps up to this depth count as touching (MotionTolerances.ContactSlop)
    private const float Left = 0.005f; // mm of overlap the response leaves (under the slop)

    [Fact]
    public void TheReportedOverlapIsTheDeepestLeftWhenEveryBodyRestsOnTheWall()
    {
        // Balls in a column against the right wall, pushed into it every step: each meets it
        // every step, so every pair is one of the touched bodies' and the report must equal a
        // fresh measurement of all pairs, and be the small overlap the response leaves.
        var world = new MotionWorld();
        world.AddWalls(new Field(3000f, 2000f, goalBlocks: false));
        var balls = new BodyId[6];
        for (int i = 0; i < balls.Length; i++)
        {
            balls[i] = world.AddCircle(40f + (5f * i), new Vector2(1500f - (40f + (5f * i)) - (3f * i), -750f + (300f * i)));
        }

        var handler = new RecordingHandler(leaveOverlap: Left) { Record = false };
        for (int step = 0; step < 12; step++)
        {
            for (int i = 0; i < balls.Length; i++)
            {
                world.SetVelocity(balls[i], new Vector2(200f + (50f * i), 0f));
            }

            world.Step(0.1f, handler);
            float measured = world.MeasureOverlap();
            Assert.True(world.Events >= balls.Length, $"step {step}: {world.Events} events, every ball should meet the wall");
            Assert.Equal(measured, world.LeftoverOverlap);
            Assert.InRange(world.LeftoverOverlap, 0.5f * Left, 2f * Left);
        }
    }

    [Theory]
    [InlineData(1)]
    [InlineData(2)]
    [InlineData(3)]
    public void TheReportedOverlapNeverExceedsAFreshMeasurementBeyondTouching(int seed)
    {
        // Random balls, some meeting, some not: the report covers the touched bodies' pairs, a
        // subset of all pairs, so it is at most the deepest overlap of all pairs now, or a touching
        // depth (under the 0.01 mm slop) sampled at the very end before a later contact moved the pair.
        var random = new Random(seed);
        var world = new MotionWorld();
        world.AddWalls(new Field(2000f, 1500f, goalBlocks: false));
        for (int i = 0; i < 30; i++)
        {
            BodyId b = world.AddCircle(30f + (20f * random.NextSingle()), new Vector2((1600f * random.NextSingle()) - 800f, (1100f * random.NextSingle()) - 550f));
            world.SetVelocity(b, new Vector2((3000f * random.NextSingle()) - 1500f, (3000f * random.NextSingle()) - 1500f));
        }

        var handler = new RecordingHandler(leaveOverlap: Left) { Record = false };
        world.Settle(handler);
        for (int step = 0; step < 30; step++)
        {
            world.Step(0.1f, handler);
            float measured = world.MeasureOverlap();
            Assert.True(world.LeftoverOverlap <= MathF.Max(measured, Slop), $"seed {seed}, step {step}: reported {world.LeftoverOverlap} mm, measured {measured} mm");
        }
    }
}
