using URWPGSim2D.Engine.Items.Demo;

namespace URWPGSim2D.Server.Tests.Items.Demo;

/// <summary>The path chooser's pieces that must match a plain scalar rule exactly.</summary>
public sealed class ApproachTests
{
    [Fact]
    public void FirstOfLeastIsWhatAScanKeepingTheFirstStrictlySmallerFinds()
    {
        var rng = new Random(41);
        for (int trial = 0; trial < 5_000; trial++)
        {
            // Few distinct values, so ties are common; signed zeros among them.
            var values = new float[1 + rng.Next(200)];
            float[] pool = [0f, -0f, 1.5f, -2.25f, 3f, float.MaxValue, -float.MaxValue, rng.NextSingle()];
            int distinct = 1 + rng.Next(pool.Length);
            for (int i = 0; i < values.Length; i++)
            {
                values[i] = pool[rng.Next(distinct)];
            }

            int scan = 0;
            for (int j = 1; j < values.Length; j++)
            {
                if (values[j] < values[scan])
                {
                    scan = j;
                }
            }

            Assert.True(scan == Approach.FirstOfLeast(values), $"trial {trial}: [{string.Join(", ", values)}]");
        }
    }
}
