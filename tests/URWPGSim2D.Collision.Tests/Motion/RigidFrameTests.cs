namespace URWPGSim2D.Collision.Tests.Motion;

/// <summary>
/// <see cref="RigidFrame.ToWorld(ReadOnlySpan{Vector2}, Span{Vector2})"/> (four points per vector)
/// answers what <see cref="RigidFrame.ToWorld(Vector2)"/> answers for each point, to the bit.
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
    public void ToWorldOfASpanRejectsAShortDestination()
    {
        var frame = new RigidFrame(Vector2.Zero, 0f, new Vector2(1f, 2f), 0.5f);
        var e = Assert.Throws<ArgumentException>(() => frame.ToWorld(new Vector2[5], new Vector2[4]));
        Assert.Equal("world", e.ParamName);
    }
}
