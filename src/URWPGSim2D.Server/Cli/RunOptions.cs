using System;
using System.Collections.Generic;
using System.Globalization;

namespace URWPGSim2D.Server.Cli;

/// <summary>The parsed arguments of <c>run</c>.</summary>
internal sealed class RunOptions
{
    /// <summary>The command's synopsis in the program's help.</summary>
    public const string Synopsis = "run [--scenario FILE] [options]";

    /// <summary>The command's full usage.</summary>
    public const string Usage = "run [--scenario FILE | --crowd N] [--cycles N] [--seed S] [--noise on|off] [--strategy TEAM=DLL[#Type]]... [--strategy-timeout MS] [--trace FILE] [--svg FILE] [--html FILE] [--live [--port N] [--host H] [--speed X] [--paused]] [--batch N [--shard I/K] [--threads P] [--results FILE]]";

    /// <summary>Largest batch.</summary>
    public const int MaximumBatch = 100_000_000;

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

    /// <summary>Replay page output file (<c>--html FILE</c>), or null.</summary>
    public string? Html { get; private set; }

    /// <summary>Whether to serve the match live in the browser (<c>--live</c>).</summary>
    public bool Live { get; private set; }

    /// <summary>Port of the live view (<c>--port N</c>).</summary>
    public int Port { get; private set; } = DefaultPort;

    /// <summary>Address the live view listens on (<c>--host H</c>; loopback by default).</summary>
    public string Host { get; private set; } = "127.0.0.1";

    /// <summary>Live playing speed, multiple of real time (<c>--speed X</c>; 1 = 100 ms a cycle).</summary>
    public double Speed { get; private set; } = 1;

    /// <summary>Whether the live match waits for resume or step before its first cycle (<c>--paused</c>).</summary>
    public bool Paused { get; private set; }

    /// <summary>Default port of the live view.</summary>
    public const int DefaultPort = 8080;

    /// <summary>Per team (0, 1), a strategy assembly spec or null.</summary>
    public string?[] Strategies { get; } = new string?[2];

    /// <summary>Time limit of a loaded strategy per cycle, ms.</summary>
    public int StrategyTimeoutMs { get; private set; } = global::URWPGSim2D.Server.Scenario.MatchBuilder.DefaultStrategyTimeoutMs;

    /// <summary>Whether --help was given.</summary>
    public bool Help { get; private set; }

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

            if (!name.StartsWith("--", StringComparison.Ordinal))
            {
                throw UsageError($"unexpected argument {CliText.Quote(name)}");
            }

            if (name is "--live" or "--paused")
            {
                if (!seen.Add(name))
                {
                    throw UsageError($"{name} given twice");
                }

                o.Live |= name == "--live";
                o.Paused |= name == "--paused";
                continue;
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
                case "--crowd": o.Crowd = (int)Number(name, value, global::URWPGSim2D.Server.Scenario.CrowdScenario.MinimumMovers, 1_000_000); break;
                case "--batch": o.Batch = (int)Number(name, value, 1, MaximumBatch); break;
                case "--threads": o.Threads = (int)Number(name, value, 1, 1024); break;
                case "--results": o.Results = value; break;
                case "--shard": o.ParseShard(value); break;
                case "--trace": o.Trace = value; break;
                case "--svg": o.Svg = value; break;
                case "--html": o.Html = value; break;
                case "--port": o.Port = (int)Number(name, value, 1, 65535); break;
                case "--host": o.Host = value.Length > 0 && !value.Contains('/', StringComparison.Ordinal) ? value : throw UsageError($"--host must be an address or host name, got {CliText.Quote(value)}"); break;
                case "--speed":
                    o.Speed = double.TryParse(value, NumberStyles.AllowDecimalPoint, CultureInfo.InvariantCulture, out double x) && x >= 0.01 && x <= 1000
                        ? x : throw UsageError($"--speed must be a number 0.01..1000 (times real time), got {CliText.Quote(value)}");
                    break;
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

        o.Check(seen);
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
    private void Check(HashSet<string> seen)
    {
        if (Help)
        {
            return;
        }

        if (Scenario is not null && Crowd is not null)
        {
            throw UsageError("--scenario and --crowd both choose the scene; give one");
        }

        if (Batch is null && (ShardCount > 1 || Threads is not null || Results is not null))
        {
            throw UsageError("--shard, --threads and --results belong to --batch N");
        }

        if (Batch is not null && (Trace is not null || Svg is not null || Html is not null))
        {
            throw UsageError("--trace, --svg and --html record one match; they do not go with --batch");
        }

        if (!Live && (seen.Contains("--port") || seen.Contains("--host") || seen.Contains("--speed") || Paused))
        {
            throw UsageError("--port, --host, --speed and --paused belong to --live");
        }

        if (Live && (Batch is not null || Trace is not null || Svg is not null || Html is not null))
        {
            throw UsageError("--live plays the match in the browser; --batch, --trace, --svg and --html do not go with it");
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
