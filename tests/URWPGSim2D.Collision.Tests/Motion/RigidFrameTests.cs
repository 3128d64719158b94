namespace URWPGSim2D.Collision.Tests.Motion;

/// <summary>
/// <see cref="RigidFrame.ToWorld(ReadOnlySpan{Vector2}, Span{Vector2})"/> (four points per vector)
/// answers what <see cref="RigidFrame.ToWorld(Vector2)"/> answers for each point, to the bit; a
/// frame moved to other positions with its turn kept (<see cref="RigidFrame.Moved"/>), and a fish's
/// frame after it moved (<see cref="Body.Frame"/>), are the frames the constructor builds for them,
/// to the bit.
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
                AssertSameBits(new RigidFrame(from, fromHeading, to, toHeading), first.Moved(from, to), Point());
            }
            catch (XunitException e)
            {
                throw RandomCaseException.At(89, trial, e);
            }
        }
    }

    [Fact]
    public void AFishsFrameAfterAMoveIsTheFrameBuiltForItsPoseBitForBit()
    {
        // Body.Frame reuses the last frame's turn only for the same turn: a fish moved without
        // turning, then turned, then moved again, each time against a frame built from scratch.
        var rng = new Random(97);
        var pose = new FishPose(new Vector2(120.5f, -340.25f), 0.7f, 0.1f, -0.2f, 0.3f);
        Body fish = Body.Fish(0, FishSize.Default, pose);
        for (int move = 0; move < 200; move++)
        {
            try
            {
                fish.Position += new Vector2((float)((rng.NextDouble() * 40) - 20), (float)((rng.NextDouble() * 40) - 20));
                if (move % 3 == 2)
                {
                    fish.Heading += (float)((rng.NextDouble() * 0.2) - 0.1);
                }

                fish.Invalidate();
                FishPose posed = fish.RigidModel.Pose;
                AssertSameBits(new RigidFrame(posed.Position, posed.Heading, fish.Position, fish.Heading), fish.Frame, new Vector2(33f, -71f));
            }
            catch (XunitException e)
            {
                throw RandomCaseException.At(97, move, e);
            }
        }
    }

    // The two frames carry points, turn vectors and combine with another frame to the same bits.
    private static void AssertSameBits(in RigidFrame expected, in RigidFrame actual, Vector2 point)
    {
        Assert.Equal(Bits(expected.Turn), Bits(actual.Turn));
        Assert.Equal(expected.IsIdentity, actual.IsIdentity);
        Assert.Equal(expected.IsTranslation, actual.IsTranslation);
        Assert.Equal(Bits(expected.ToWorld(point)), Bits(actual.ToWorld(point)));
        Assert.Equal(Bits(expected.ToModel(point)), Bits(actual.ToModel(point)));
        Assert.Equal(Bits(expected.Rotate(point)), Bits(actual.Rotate(point)));
        var other = new RigidFrame(new Vector2(5f, 6f), 0.3f, new Vector2(-7f, 8f), 1.1f);
        RigidFrame.Between(expected, other, out Vector2 rotationExpected, out Vector2 translationExpected);
        RigidFrame.Between(actual, other, out Vector2 rotationActual, out Vector2 translationActual);
        Assert.Equal(Bits(rotationExpected), Bits(rotationActual));
        Assert.Equal(Bits(translationExpected), Bits(translationActual));
    }

    private static int Bits(float value) => BitConverter.SingleToInt32Bits(value);

    private static (int X, int Y) Bits(Vector2 value) => (Bits(value.X), Bits(value.Y));

    [Fact]
    public void ToWorldOfASpanRejectsAShortDestination()
    {
        var frame = new RigidFrame(Vector2.Zero, 0f, new Vector2(1f, 2f), 0.5f);
        var e = Assert.Throws<ArgumentException>(() => frame.ToWorld(new Vector2[5], new Vector2[4]));
        Assert.Equal("world", e.ParamName);
    }
}
