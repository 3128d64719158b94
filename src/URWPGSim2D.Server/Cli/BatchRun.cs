using System.Diagnostics;
using URWPGSim2D.Tournament.Batch;
using URWPGSim2D.Engine.Scenario;

namespace URWPGSim2D.Server.Cli;

/// <summary>
/// <c>run --batch N</c>: plays this process's shard of a batch (every match when there is one
/// shard) on <c>--threads</c> threads (default: every core), prints one line per match in match
/// order and the aggregate, and writes <c>--results FILE</c> for <c>merge</c>. See docs/batch.md.
/// </summary>
internal static class BatchRun
{
    /// <summary>Runs the batch; returns the exit code.</summary>
    public static int Run(RunOptions options, ScenarioDefinition scenario, string scene, CliConsole console)
    {
        int matches = options.Batch!.Value;
        ulong first = options.Seed ?? scenario.Seed;
        if (first > long.MaxValue - (ulong)matches)
        {
            console.ErrorLine($"run: --batch {matches} from seed {first} would need seeds beyond {long.MaxValue}");
            return ExitCodes.BadInput;
        }

        int cycles = options.CyclesFor(scenario);
        var header = new BatchHeader(
            scene, StrategiesText(options), TeamsText(scenario, options), NoiseText(options), options.StrategyTimeoutMs, first,
            matches, cycles, options.ShardIndex, options.ShardCount);
        if (options.Slurm is not null)
        {
            return SlurmRun.Run(options, header, console);
        }

        if (options.Results is { } path && !CanWrite(path + ".partial", console))
        {
            return ExitCodes.BadInput;
        }

        int threads = options.Threads ?? Environment.ProcessorCount;

        var clock = Stopwatch.StartNew();
        MatchResult[] results;
        try
        {
            results = BatchRunner.Run(
                header,
                threads,
                seed => (RunCommand.Settings(options, scenario, RunCommand.LoadTeams(options)) with { Seed = seed, Threads = 1 }).Build(),
                r => console.Out.Write(BatchSummary.Line(r)));
            clock.Stop();
            if (options.Results is { } file)
            {
                ResultFile.Write(file, header, results);
            }
        }
        finally
        {
            if (options.Results is { } file && File.Exists(file + ".partial"))
            {
                File.Delete(file + ".partial");
            }
        }

        console.Out.Write(BatchSummary.Aggregate(header, results));
        double seconds = Math.Max(clock.Elapsed.TotalSeconds, 1e-9);
        double simulated = results.Length * cycles * 0.1;
        console.Out.Write(string.Create(CultureInfo.InvariantCulture, $"wall time: {seconds:0.000} s on {threads} threads, {results.Length / seconds:0.00} matches/s, {simulated / seconds:0}x real time\n"));
        RunCommand.Wrote(console, options.Results, string.Create(CultureInfo.InvariantCulture, $"the results of {results.Length} matches"));
        int failed = results.Count(r => r.Failed is not null);
        if (failed > 0)
        {
            console.ErrorLine(string.Create(CultureInfo.InvariantCulture, $"run: {failed} matches failed inside the server; each has its line with \"failed\" and the reason"));
            return ExitCodes.InternalError;
        }

        return ExitCodes.Success;
    }

    private static bool CanWrite(string path, CliConsole console)
    {
        try
        {
            File.WriteAllText(path, string.Empty);
            return true;
        }
        catch (Exception e) when (e is IOException or UnauthorizedAccessException or ArgumentException or NotSupportedException)
        {
            console.ErrorLine($"--results: cannot write {path} ({e.Message})");
            return false;
        }
    }

    private static string StrategiesText(RunOptions options)
    {
        var given = new List<string>();
        for (int t = 0; t < options.Strategies.Length; t++)
        {
            if (options.Strategies[t] is { } spec)
            {
                given.Add(string.Create(System.Globalization.CultureInfo.InvariantCulture, $"{t}={spec}"));
            }
        }

        return string.Join(";", given);
    }

    private static string TeamsText(ScenarioDefinition scenario, RunOptions options)
    {
        var probe = MatchBuilder.Build(scenario, RunCommand.LoadTeams(options), options.Seed, options.Noise, options.StrategyTimeoutMs);
        probe.Teams.Stop();
        var labels = new List<string>();
        for (int t = 0; t < probe.TeamCount; t++)
        {
            labels.Add(probe.TeamLabel(t));
        }

        return string.Join(";", labels);
    }

    private static string NoiseText(RunOptions options) => options.Noise switch
    {
        true => "on",
        false => "off",
        null => "scenario",
    };
}
