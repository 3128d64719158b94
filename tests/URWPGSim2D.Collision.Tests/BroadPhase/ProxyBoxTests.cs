namespace URWPGSim2D.Collision.Tests.BroadPhase;

/// <summary>
/// The packed overlap test (one vector comparison of (min, −max) against (max, −min)) answers
/// exactly what the four scalar comparisons of closed boxes answer: random boxes, boxes touching
/// exactly on an edge or a corner, flat and point boxes, signed zeros, infinite and NaN bounds.
/// </summary>
public sealed class ProxyBoxTests
{
    private const int Seed = 515;

    private static readonly float[] Special = [0f, -0f, 1f, -1f, float.PositiveInfinity, float.NegativeInfinity, float.NaN, 1e-30f, 3.5f];

    [Fact]
    public void PackedOverlapAnswersAsTheScalarOne()
    {
        var random = new Random(Seed);
        int overlapping = 0, apart = 0;
        for (int trial = 0; trial < 50_000; trial++)
        {
            try
            {
                Vector2 minA = Corner(random), maxA = minA + Size(random);
                Vector2 minB = Corner(random), maxB = minB + Size(random);
                switch (trial % 6)
                {
                    case 0:
                        minB = new Vector2(maxA.X, minB.Y); // touching on an edge of A
                        break;
                    case 1:
                        (minB, maxB) = (maxA, maxA + Size(random)); // touching at a corner
                        break;
                    case 2:
                        minA = new Vector2(Pick(random), Pick(random));
                        maxB = new Vector2(Pick(random), Pick(random));
                        break;
                }

                bool expected = ProxyBox.Overlap(minA, maxA, minB, maxB);
                Assert.Equal(expected, ProxyBox.Overlap(ProxyBox.Reach(ProxyBox.Packed(minA, maxA)), ProxyBox.Packed(minB, maxB)));
                Assert.Equal(ProxyBox.Overlap(minB, maxB, minA, maxA), ProxyBox.Overlap(ProxyBox.Reach(ProxyBox.Packed(minB, maxB)), ProxyBox.Packed(minA, maxA)));
                overlapping += expected ? 1 : 0;
                apart += expected ? 0 : 1;
            }
            catch (XunitException e)
            {
                throw RandomCaseException.At(Seed, trial, e);
            }
        }

        Assert.True(overlapping > 5_000 && apart > 5_000, $"{overlapping} overlapping and {apart} apart cases: the generator no longer covers both");
    }

    private static Vector2 Corner(Random random) => new(((float)random.NextDouble() - 0.5f) * 1000f, ((float)random.NextDouble() - 0.5f) * 1000f);

    private static Vector2 Size(Random random) => random.Next(8) == 0 ? Vector2.Zero : new Vector2((float)random.NextDouble() * 400f, (float)random.NextDouble() * 400f);

    private static float Pick(Random random) => Special[random.Next(Special.Length)];
}
