namespace URWPGSim2D.Collision.Tests.Motion;

/// <summary>
/// <see cref="Disc.LeastGap"/> (four circle gaps at once) answers exactly what the four scalar
/// gaps <see cref="Disc.GapTo(in Disc)"/> and their minimum answer, to the bit: random circles
/// over the coordinates a pool reaches and beyond, equal and touching circles, one inside another.
/// </summary>
public sealed class DiscTests
{
    private const int Seed = 4242;

    [Fact]
    public void LeastGapIsTheLeastOfTheFourGapsBitForBit()
    {
        var random = new Random(Seed);
        for (int trial = 0; trial < 20_000; trial++)
        {
            try
            {
                float scale = trial % 3 == 0 ? 50_000f : trial % 3 == 1 ? 3_000f : 400f;
                Disc a1 = RandomDisc(random, scale), a2 = RandomDisc(random, scale);
                Disc b1 = RandomDisc(random, scale), b2 = RandomDisc(random, scale);
                switch (trial % 5)
                {
                    case 0:
                        b2 = a1; // the same circle: gap −2r
                        break;
                    case 1:
                        b1 = new Disc(a2.Center + new Vector2(a2.Radius + 20f, 0f), 20f); // touching
                        break;
                }

                float expected = MathF.Min(MathF.Min(a1.GapTo(b1), a1.GapTo(b2)), MathF.Min(a2.GapTo(b1), a2.GapTo(b2)));
                float actual = Disc.LeastGap(a1, a2, b1, b2);
                Assert.Equal(BitConverter.SingleToInt32Bits(expected), BitConverter.SingleToInt32Bits(actual));
            }
            catch (XunitException e)
            {
                throw RandomCaseException.At(Seed, trial, e);
            }
        }
    }

    private static Disc RandomDisc(Random random, float scale) =>
        new(new Vector2(((float)random.NextDouble() - 0.5f) * scale, ((float)random.NextDouble() - 0.5f) * scale), (float)random.NextDouble() * 400f);
}
