using System;
using System.Collections.Generic;

namespace URWPGSim2D.Collision.Samples;

/// <summary>Runs every sample; exit code 1 when one fails. Add a new sample to <see cref="All"/>.</summary>
internal static class Program
{
    private static readonly IReadOnlyList<(string Name, Action Run)> All =
    [
        ("Readme/UsingTheLibrary", Readme.UsingTheLibrary.Run),
        ("Queries/SensingTheWay", Queries.SensingTheWay.Run),
    ];

    private static int Main()
    {
        int failed = 0;
        foreach (var (name, run) in All)
        {
            try
            {
                run();
                Console.WriteLine($"sample {name}: ok");
            }
            catch (Exception e)
            {
                Console.WriteLine($"sample {name}: FAILED: {e.Message}");
                failed++;
            }
        }

        return failed == 0 ? 0 : 1;
    }
}
