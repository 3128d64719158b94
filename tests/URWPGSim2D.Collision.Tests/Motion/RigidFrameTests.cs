namespace URWPGSim2D.Collision.Tests.Motion;

/// <summary>
/// <see cref="RigidFrame.ToWorld(ReadOnlySpan{Vector2}, Span{Vector2})"/> (four points per vector)
/// answers what <see cref="RigidFrame.ToWorld(Vector2)"/> answers for each point, to the bit; a
/// frame moved to other positions with its turn kept (<see cref="RigidFrame.Moved"/>) is the frame
/// the constructor builds for them, to the bit.
/// </summary>
public sealed class RigidFrameTests
{
    [Fact]
    public void ToWorldOfASpanEqualsThePointByPointMoveBitForBit()
    {
        // The vector path (four points per register, the last block overlapping) must not change a
        // single bit: every length from 0 to 31 (a fish's 31 leaf vertices), turned and untouched frames.
        var rng = new Random(83);
        for (int trial = 0; trial < 2000; trial++)
        {
            try
            {
                int n = trial % 32;
                var model = new Vector2[n];
                for (int i = 0; i < n; i++)
                {
                    model[i] = new Vector2((float)((rng.NextDouble() * 50000) - 25000), (float)((rng.NextDouble() * 50000) - 25000));
                }

                var from = new Vector2((float)((rng.NextDouble() * 50000) - 25000), (float)((rng.NextDouble() * 50000) - 25000));
                var to = from + new Vector2((float)((rng.NextDouble() * 400) - 200), (float)((rng.NextDouble() * 400) - 200));
                float heading = (float)((rng.NextDouble() * 20) - 10);
                float turn = trial % 5 == 0 ? 0f : (float)((rng.NextDouble() * 0.4) - 0.2);
                var frame = new RigidFrame(from, heading, to, heading + turn);
                var world = new Vector2[n + 1];
                world[n] = new Vector2(7f, 11f);
                frame.ToWorld(model, world);
                for (int i = 0; i < n; i++)
                {
                    Assert.Equal(frame.ToWorld(model[i]), world[i]);
                }

                Assert.Equal(new Vector2(7f, 11f), world[n]);
            }
            catch (XunitException e)
            {
                throw RandomCaseException.At(83, trial, e);
            }
        }
    }

    [Fact]
    public void AFrameMovedWithItsTurnIsTheFrameBuiltForTheNewPositionsBitForBit()
    {
        // A fish's frame keeps the sine and cosine of its last turn when it moves without turning
        // (Body.Frame): every move, carry and flag must be the constructor's for the same turn.
        var rng = new Random(89);
        for (int trial = 0; trial < 2000; trial++)
        {
            try
            {
                Vector2 Point() => new((float)((rng.NextDouble() * 50000) - 25000), (float)((rng.NextDouble() * 50000) - 25000));
                float fromHeading = (float)((rng.NextDouble() * 20) - 10);
                float toHeading = trial % 4 == 0 ? fromHeading : fromHeading + (float)((rng.NextDouble() * 0.4) - 0.2);
                var first = new RigidFrame(Point(), fromHeading, Point(), toHeading);
                Vector2 from = Point(), to = trial % 7 == 0 ? from : Point();
                RigidFrame moved = first.Moved(from, to);
                var built = new RigidFrame(from, fromHeading, to, toHeading);
                Assert.Equal(built.Turn, moved.Turn);
                Assert.Equal(built.IsIdentity, moved.IsIdentity);
                Assert.Equal(built.IsTranslation, moved.IsTranslation);
                Vector2 p = Point();
                Assert.Equal(built.ToWorld(p), moved.ToWorld(p));
                Assert.Equal(built.ToModel(p), moved.ToModel(p));
                RigidFrame.Between(built, first, out Vector2 rotationBuilt, out Vector2 translationBuilt);
                RigidFrame.Between(moved, first, out Vector2 rotationMoved, out Vector2 translationMoved);
                Assert.Equal(rotationBuilt, rotationMoved);
                Assert.Equal(translationBuilt, translationMoved);
            }
            catch (XunitException e)
            {
                throw RandomCaseException.At(89, trial, e);
            }
        }
    }

    [Fact]
    public void ToWorldOfASpanRejectsAShortDestination()
    {
        var frame = new RigidFrame(Vector2.Zero, 0f, new Vector2(1f, 2f), 0.5f);
        var e = Assert.Throws<ArgumentException>(() => frame.ToWorld(new Vector2[5], new Vector2[4]));
        Assert.Equal("world", e.ParamName);
    }
}
