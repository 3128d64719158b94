using System.Linq;
using BenchmarkDotNet.Reports;
using BenchmarkDotNet.Running;
using URWPGSim2D.Collision.Benchmarks.Scaling;

namespace URWPGSim2D.Collision.Benchmarks;

/// <summary>
/// Entry point: <c>dotnet run -c Release --project benchmarks/URWPGSim2D.Collision.Benchmarks -- --filter '*'</c>.
/// Everything after <c>--</c> goes to BenchmarkDotNet's switcher, except <c>--plot FILE</c>: after
/// the run, the scaling and broad-phase results (medians per cycle) are drawn into FILE as SVG.
/// </summary>
public static class Program
{
    /// <summary>Runs the benchmarks chosen on the command line.</summary>
    /// <param name="args">BenchmarkDotNet arguments, e.g. <c>--filter *Pair*</c> or <c>--job dry</c>, plus <c>--plot FILE</c>.</param>
    /// <returns>
    /// 0 when every chosen benchmark produced a result; 1 when any failed (a validation error, an
    /// exception, an NA row), when a <c>--filter</c> matched nothing, or when the plot had nothing to draw.
    /// </returns>
    public static int Main(string[] args)
    {
        int at = Array.IndexOf(args, "--plot");
        string? plot = at >= 0 && at + 1 < args.Length ? args[at + 1] : null;
        string[] rest = at >= 0 ? [.. args[..at], .. args[Math.Min(args.Length, at + 2)..]] : args;
        if (!rest.Contains("--artifacts") && DefaultArtifacts() is { } artifacts)
        {
            rest = [.. rest, "--artifacts", artifacts];
        }

        var summaries = BenchmarkSwitcher.FromAssembly(typeof(Program).Assembly).Run(rest).ToArray();
        var errors = Errors(summaries, filtered: rest.Contains("--filter")).ToList();
        foreach (string error in errors)
        {
            Console.Error.WriteLine("benchmark error: " + error);
        }

        if (plot is not null)
        {
            var series = Series(summaries);
            if (series.Count == 0)
            {
                Console.Error.WriteLine("--plot: no ScalingBenchmarks or BroadPhaseBenchmarks results to draw");
                return 1;
            }

            ScalingPlot.Write(plot, "Cost per cycle against object count (median, this machine)", series);
            Console.WriteLine($"plot written to {plot}");
        }

        return errors.Count == 0 ? 0 : 1;
    }

    /// <summary>
    /// benchmarks/artifacts of the clone this program was built in (git-ignored), so a run from the
    /// repository root leaves no BenchmarkDotNet.Artifacts folder there; null outside a clone.
    /// </summary>
    private static string? DefaultArtifacts()
    {
        for (var folder = new DirectoryInfo(AppContext.BaseDirectory); folder is not null; folder = folder.Parent)
        {
            if (File.Exists(Path.Combine(folder.FullName, "URWPGSim2D.Collision.sln")))
            {
                return Path.Combine(folder.FullName, "benchmarks", "artifacts");
            }
        }

        return null;
    }

    /// <summary>Every failure of a run: validation errors, and each case without a result (BenchmarkDotNet's NA rows).</summary>
    /// <param name="summaries">The summaries the switcher returned.</param>
    /// <param name="filtered">Whether a <c>--filter</c> was given (then no summary at all is a failure).</param>
    /// <returns>One line per failure.</returns>
    public static IEnumerable<string> Errors(IReadOnlyCollection<Summary> summaries, bool filtered)
    {
        if (filtered && summaries.Sum(s => s.BenchmarksCases.Length) == 0)
        {
            yield return "the filter matched no benchmark";
        }

        foreach (var summary in summaries)
        {
            foreach (var error in summary.ValidationErrors)
            {
                yield return (error.IsCritical ? "critical validation error: " : "validation error: ") + error.Message.ReplaceLineEndings(" ");
            }

            foreach (var benchmark in summary.BenchmarksCases)
            {
                var report = summary.Reports.FirstOrDefault(r => r.BenchmarkCase == benchmark);
                if (report is null || !report.Success || report.ResultStatistics is null)
                {
                    yield return $"{benchmark.DisplayInfo}: no result (it threw, or the run failed; see the log above)";
                }
            }
        }
    }

    // One series per (benchmark class, method) of the scaling and broad-phase benchmarks.
    private static List<ScalingPlot.Series> Series(IEnumerable<Summary> summaries)
    {
        var lines = new Dictionary<string, List<(double, double)>>();
        foreach (var summary in summaries)
        {
            foreach (var report in summary.Reports)
            {
                var c = report.BenchmarkCase;
                string type = c.Descriptor.Type.Name;
                string? label = type switch
                {
                    nameof(ScalingBenchmarks) => c.Descriptor.WorkloadMethod.Name == "Grid" ? "whole cycle: grid" : "whole cycle: frozen baseline (grid)",
                    nameof(BruteForceScalingBenchmarks) => "whole cycle: brute force",
                    "BroadPhaseBenchmarks" => "broad phase alone: " + c.Descriptor.WorkloadMethod.Name switch
                    {
                        "Grid" => "grid",
                        "SweepAndPrune" => "sweep and prune",
                        "DynamicTree" => "AABB tree",
                        _ => "brute force",
                    },
                    _ => null,
                };
                var stats = report.ResultStatistics;
                var objects = c.Parameters.Items.FirstOrDefault(p => p.Name == "Objects")?.Value;
                if (label is null || stats is null || objects is null)
                {
                    continue;
                }

                if (!lines.TryGetValue(label, out var points))
                {
                    lines[label] = points = [];
                }

                points.Add((Convert.ToDouble(objects, System.Globalization.CultureInfo.InvariantCulture), stats.Median));
            }
        }

        // The whole cycle on the grid first: it sets the slope-1 guide.
        return lines.OrderBy(l => l.Key == "whole cycle: grid" ? 0 : l.Key.StartsWith("whole", StringComparison.Ordinal) ? 1 : 2).ThenBy(l => l.Key, StringComparer.Ordinal)
            .Select(l => new ScalingPlot.Series(l.Key, l.Value)).ToList();
    }
}
