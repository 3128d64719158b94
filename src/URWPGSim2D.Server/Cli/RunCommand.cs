using System;
using System.Diagnostics;
using System.IO;
using URWPGSim2D.Server.Rendering;
using URWPGSim2D.Server.Scenario;
using URWPGSim2D.Server.Simulation;
using URWPGSim2D.Server.Strategies;
using URWPGSim2D.Server.Trace;

namespace URWPGSim2D.Server.Cli;

/// <summary>
/// <c>run</c>: plays a match (the embedded default match, or <c>--scenario FILE</c>) and prints a
/// summary; optionally writes a JSON Lines trace and an SVG of the final frame. A progress bar is
/// drawn only when standard output is a terminal. Bad input (arguments, scenario, strategy
/// assembly) is one line on stderr and exit code 2, with no output file written.
/// </summary>
internal sealed class RunCommand : ICliCommand
{
    /// <inheritdoc/>
    public string Name => "run";

    /// <inheritdoc/>
    public string Synopsis => RunOptions.Synopsis;

    /// <inheritdoc/>
    public string Summary => "Play a match (default: the embedded 2-vs-2 match, 3,000 cycles) and print a summary.";

    /// <inheritdoc/>
    public int Run(ReadOnlySpan<string> arguments, CliConsole console)
    {
        var options = RunOptions.Parse(arguments);
        if (options.Help)
        {
            console.Out.Write(HelpText());
            return ExitCodes.Success;
        }

        ScenarioDefinition scenario;
        try
        {
            scenario = options.Scenario is null ? DefaultScenario.Load() : ScenarioParser.Parse(ReadScenario(options.Scenario, console));
        }
        catch (ScenarioException e)
        {
            console.Error.WriteLine(e.Message);
            return ExitCodes.BadInput;
        }

        var teams = new TeamStrategy?[2];
        for (int t = 0; t < 2; t++)
        {
            if (options.Strategies[t] is { } spec)
            {
                try
                {
                    teams[t] = new TeamStrategy(Path.GetFileName(spec), StrategyLoader.Load(spec), Isolated: true);
                }
                catch (StrategyLoadException e)
                {
                    console.Error.WriteLine($"--strategy {t}: {e.Message}");
                    return ExitCodes.BadInput;
                }
            }
        }

        var match = MatchBuilder.Build(scenario, teams, options.Seed, options.Noise, options.StrategyTimeoutMs);
        int cycles = options.Cycles ?? scenario.Cycles;
        bool interactive = ReferenceEquals(console.Out, Console.Out) && !Console.IsOutputRedirected;
        var progress = interactive ? new ProgressBar(console.Out, cycles) : null;
        var clock = Stopwatch.StartNew();
        using (var trace = options.Trace is null ? null : new TraceWriter(options.Trace))
        {
            trace?.WriteCycle(match.World, ReadOnlySpan<ContactRecord>.Empty);
            for (int k = 0; k < cycles; k++)
            {
                match.Step();
                trace?.WriteCycle(match.World, match.Contacts.Cycle);
                progress?.Update(k + 1);
            }

            trace?.Complete();
        }

        clock.Stop();
        progress?.Clear();
        if (options.Svg is not null)
        {
            foreach (var fish in match.World.Fish)
            {
                fish.SyncModel(); // the picture shows every leaf exactly where the fish is
            }

            SvgFrame.Write(match.World, options.Svg);
        }

        console.Out.Write(MatchSummary.Format(match, clock.Elapsed));
        return ExitCodes.Success;
    }

    private static string ReadScenario(string path, CliConsole console)
    {
        try
        {
            return path == "-" ? console.In.ReadToEnd() : File.ReadAllText(path);
        }
        catch (Exception e) when (e is IOException or UnauthorizedAccessException or ArgumentException or NotSupportedException)
        {
            throw new ScenarioException(path, $"cannot read the scenario file ({e.Message})");
        }
    }

    private static string HelpText() =>
        $"Usage: {CliApp.ProgramName} {RunOptions.Usage}\n\n" +
        "Plays a match of 100 ms cycles and prints cycles, simulated and wall time, goals per team, contacts by pair\n" +
        "kind, sub-steps, the largest leftover overlap and strategy faults. Without --scenario it plays the embedded\n" +
        "default match. --strategy TEAM=My.dll loads a compiled IStrategy for a whole team (its own load context,\n" +
        "--strategy-timeout ms per cycle, default 100). --trace writes JSON Lines, --svg the final frame.\n" +
        "Formats: docs/scenario.md, docs/simulation.md.\n";
}
