using URWPGSim2D.Testing;
using Xunit.Sdk;

namespace URWPGSim2D.Protocol.Tests;

/// <summary>How the tests here run a check many times: over seeded random cases, or in a steady state counting allocations.</summary>
internal static class Runs
{
    /// <summary>Runs <paramref name="test"/> on <paramref name="count"/> random cases drawn from <paramref name="seed"/>; a failure names its case and the seed (<see cref="RandomCaseException"/>).</summary>
    public static void RandomCases(int seed, int count, Action<Random> test)
    {
        var random = new Random(seed);
        for (int i = 0; i < count; i++)
        {
            try
            {
                test(random);
            }
            catch (XunitException e)
            {
                throw RandomCaseException.At(seed, i, e);
            }
        }
    }

    /// <summary>The bytes <paramref name="once"/> allocates over 100 runs after two to warm up (0 in a steady state that allocates nothing).</summary>
    public static long SteadyStateAllocations(Action once)
    {
        once();
        once();
        long before = GC.GetAllocatedBytesForCurrentThread();
        for (int i = 0; i < 100; i++)
        {
            once();
        }

        return GC.GetAllocatedBytesForCurrentThread() - before;
    }
}
