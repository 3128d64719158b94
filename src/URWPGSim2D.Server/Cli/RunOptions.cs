using System;
using System.Collections.Generic;
using System.Globalization;
using URWPGSim2D.Server.Items;

namespace URWPGSim2D.Server.Cli;

/// <summary>The parsed arguments of <c>run</c>.</summary>
internal sealed class RunOptions
{
    /// <summary>The command's synopsis in the program's help.</summary>
    public const string Synopsis = "run [--item NAME | --scenario FILE] [options]";

    /// <summary>The command's full usage.</summary>
    public const string Usage = "run [--item NAME | --scenario FILE | --crowd N] [--minutes 10|5|3|1 | --cycles N] [--list-items] [--seed S] [--noise on|off] [--strategy TEAM=DLL[#Type]]... [--strategy-timeout MS] [--trace FILE] [--svg FILE] [--batch N [--shard I/K] [--threads P] [--results FILE]]";

    /// <summary>Largest batch.</summary>
    public const int MaximumBatch = 100_000_000;

    /// <summary>Competition item slug or Chinese name (<c>--item NAME</c>; "default" is the old default scene), or null.</summary>
    public string? Item { get; private set; }

    /// <summary>Match length in minutes (<c>--minutes 10|5|3|1</c>), or null.</summary>
    public int? Minutes { get; private set; }

    /// <summary>Whether <c>--list-items</c> was given.</summary>
    public bool ListItems { get; private set; }

    /// <summary>Scenario file, or null for the embedded default match.</summary>
    public string? Scenario { get; private set; }

    /// <summary>Fish and balls of a generated crowd scene (<c>--crowd N</c>), or null.</summary>
    public int? Crowd { get; private set; }

    /// <summary>Number of matches of a batch (<c>--batch N</c>), or null for a single match.</summary>
    public int? Batch { get; private set; }

    /// <summary>This process's shard of the batch: index 0 … count − 1.</summary>
    public int ShardIndex { get; private set; }

    /// <summary>How many shards the batch is split into (1: the whole batch here).</summary>
    public int ShardCount { get; private set; } = 1;

    /// <summary>Matches played at once (<c>--threads P</c>); default: every core.</summary>
    public int? Threads { get; private set; }

    /// <summary>JSON Lines result file of a batch, or null.</summary>
    public string? Results { get; private set; }

    /// <summary>Cycle count override.</summary>
    public int? Cycles { get; private set; }

    /// <summary>Seed override.</summary>
    public ulong? Seed { get; private set; }

    /// <summary>Noise override.</summary>
    public bool? Noise { get; private set; }

    /// <summary>Trace output file.</summary>
    public string? Trace { get; private set; }

    /// <summary>SVG output file.</summary>
    public string? Svg { get; private set; }

    /// <summary>Per team (0, 1), a strategy assembly spec or null.</summary>
    public string?[] Strategies { get; } = new string?[2];

    /// <summary>Time limit of a loaded strategy per cycle, ms.</summary>
    public int StrategyTimeoutMs { get; private set; } = global::URWPGSim2D.Server.Scenario.MatchBuilder.DefaultStrategyTimeoutMs;

    /// <summary>Whether --help was given.</summary>
    public bool Help { get; private set; }

    /// <summary>Cycles to play: <c>--cycles</c>, else <c>--minutes</c> × 600, else the scenario's.</summary>
    public int CyclesFor(global::URWPGSim2D.Server.Scenario.ScenarioDefinition scenario) => Cycles ?? (Minutes * 600) ?? scenario.Cycles;

    /// <summary>Parses the arguments after "run".</summary>
    public static RunOptions Parse(ReadOnlySpan<string> args)
    {
        var o = new RunOptions();
        var seen = new HashSet<string>(StringComparer.Ordinal);
        for (int i = 0; i < args.Length; i++)
        {
            string name = args[i];
            if (name is "--help" or "-h")
            {
                o.Help = true;
                continue;
            }

            if (name == "--list-items")
            {
                o.ListItems = true;
                continue;
            }

            if (!name.StartsWith("--", StringComparison.Ordinal))
            {
                throw UsageError($"unexpected argument {CliText.Quote(name)}");
            }

            if (i + 1 >= args.Length)
            {
                throw UsageError($"{name} needs a value");
            }

            string value = args[++i];
            if (name != "--strategy" && !seen.Add(name))
            {
                throw UsageError($"{name} given twice");
            }

            switch (name)
            {
                case "--scenario": o.Scenario = value; break;
                case "--item":
                    o.Item = value == "default" || ItemRegistry.Find(value) is not null
                        ? value
                        : throw UsageError($"--item must be one of {ItemRegistry.Names()} (or the original's name), got {CliText.Quote(value)}");
                    break;
                case "--minutes":
                    o.Minutes = value switch { "10" => 10, "5" => 5, "3" => 3, "1" => 1, _ => throw UsageError($"--minutes must be 10, 5, 3 or 1, got {CliText.Quote(value)}") };
                    break;
                case "--crowd": o.Crowd = (int)Number(name, value, global::URWPGSim2D.Server.Scenario.CrowdScenario.MinimumMovers, 1_000_000); break;
                case "--batch": o.Batch = (int)Number(name, value, 1, MaximumBatch); break;
                case "--threads": o.Threads = (int)Number(name, value, 1, 1024); break;
                case "--results": o.Results = value; break;
                case "--shard": o.ParseShard(value); break;
                case "--trace": o.Trace = value; break;
                case "--svg": o.Svg = value; break;
                case "--cycles": o.Cycles = (int)Number(name, value, 0, int.MaxValue); break;
                case "--seed": o.Seed = (ulong)Number(name, value, 0, long.MaxValue); break;
                case "--strategy-timeout": o.StrategyTimeoutMs = (int)Number(name, value, 1, 600_000); break;
                case "--noise":
                    o.Noise = value switch { "on" => true, "off" => false, _ => throw UsageError($"--noise must be on or off, got {CliText.Quote(value)}") };
                    break;
                case "--strategy":
                    int eq = value.IndexOf('=', StringComparison.Ordinal);
                    if (eq != 1 || value[0] is not ('0' or '1') || eq + 1 >= value.Length)
                    {
                        throw UsageError($"--strategy must be TEAM=PATH with TEAM 0 or 1, got {CliText.Quote(value)}");
                    }

                    o.Strategies[value[0] - '0'] = value[(eq + 1)..];
                    break;
                default:
                    throw UsageError($"unknown option {CliText.Quote(name)}");
            }
        }

        o.Check();
        return o;
    }

    // "I/K" with 0 ≤ I < K.
    private void ParseShard(string value)
    {
        int slash = value.IndexOf('/', StringComparison.Ordinal);
        if (slash <= 0
            || !int.TryParse(value.AsSpan(0, slash), NumberStyles.None, CultureInfo.InvariantCulture, out int index)
            || !int.TryParse(value.AsSpan(slash + 1), NumberStyles.None, CultureInfo.InvariantCulture, out int count)
            || count < 1 || index >= count)
        {
            throw UsageError($"--shard must be I/K with 0 <= I < K (e.g. 0/4), got {CliText.Quote(value)}");
        }

        ShardIndex = index;
        ShardCount = count;
    }

    // Options that do not go together.
    private void Check()
    {
        if (Help)
        {
            return;
        }

        if ((Scenario is not null ? 1 : 0) + (Crowd is not null ? 1 : 0) + (Item is not null ? 1 : 0) > 1)
        {
            throw UsageError("--item, --scenario and --crowd each choose the scene; give one");
        }

        if (Minutes is not null && Cycles is not null)
        {
            throw UsageError("--minutes and --cycles both set the length; give one");
        }

        if (Batch is null && (ShardCount > 1 || Threads is not null || Results is not null))
        {
            throw UsageError("--shard, --threads and --results belong to --batch N");
        }

        if (Batch is not null && (Trace is not null || Svg is not null))
        {
            throw UsageError("--trace and --svg record one match; they do not go with --batch");
        }
    }

    private static long Number(string name, string value, long min, long max)
    {
        if (!long.TryParse(value, NumberStyles.None, CultureInfo.InvariantCulture, out long v) || v < min || v > max)
        {
            throw UsageError($"{name} must be an integer {min}..{max}, got {CliText.Quote(value)}");
        }

        return v;
    }

    private static CliUsageException UsageError(string message) => new("run: " + message, CliApp.ProgramName + " " + Usage);
}
