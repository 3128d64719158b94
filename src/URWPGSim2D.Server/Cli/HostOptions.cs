using System;
using System.CommandLine;
using System.Globalization;
using URWPGSim2D.Server.Cli.Syntax;
using URWPGSim2D.Server.Hosting;
using URWPGSim2D.Server.Json;

namespace URWPGSim2D.Server.Cli;

/// <summary>
/// The options of where user strategies run, the same for <c>run</c> and <c>tournament</c>:
/// <c>--isolation process|none</c>, <c>--sandbox auto|required|off</c>, <c>--strategy-memory MB</c>.
/// </summary>
internal static class HostOptions
{
    /// <summary>The options in a usage line.</summary>
    public const string Usage = "[--isolation process|none] [--sandbox auto|required|off] [--strategy-memory MB]";

    /// <summary>The options' declarations, new for each command that takes them.</summary>
    public static Option[] Declare() =>
    [
        CliSyntax.Value("--isolation", "process|none", "where user strategies run", CliCompletions.Fixed("process", "none")),
        CliSyntax.Value("--sandbox", "auto|required|off", "whether strategy hosts run in the sandbox", CliCompletions.Fixed("auto", "required", "off")),
        CliSyntax.Value("--strategy-memory", "MB", "a strategy host's heap limit"),
    ];

    /// <summary>Whether <paramref name="name"/> is one of these options.</summary>
    public static bool Is(string name) => name is "--isolation" or "--sandbox" or "--strategy-memory";

    /// <summary><paramref name="settings"/> with the option <paramref name="name"/> set to <paramref name="value"/>.</summary>
    /// <param name="settings">The settings so far.</param>
    /// <param name="name">One of the options (<see cref="Is"/>).</param>
    /// <param name="value">Its value.</param>
    /// <param name="error">Makes the command's usage error from a one-line message naming the option and the value.</param>
    public static HostSettings Apply(HostSettings settings, string name, string value, Func<string, Exception> error) => name switch
    {
        "--isolation" => settings with
        {
            Isolation = value switch
            {
                "process" => IsolationMode.Process,
                "none" => IsolationMode.None,
                _ => throw error($"--isolation must be process or none, got {MessageText.Quote(value)}"),
            },
        },
        "--sandbox" => settings with
        {
            Sandbox = value switch
            {
                "auto" => SandboxMode.Auto,
                "required" => SandboxMode.Required,
                "off" => SandboxMode.Off,
                _ => throw error($"--sandbox must be auto, required or off, got {MessageText.Quote(value)}"),
            },
        },
        "--strategy-memory" => settings with
        {
            MemoryMb = int.TryParse(value, NumberStyles.None, CultureInfo.InvariantCulture, out int mb) && mb >= MinimumMemoryMb && mb <= MaximumMemoryMb
                ? mb
                : throw error($"--strategy-memory must be an integer {MinimumMemoryMb}..{MaximumMemoryMb}, got {MessageText.Quote(value)}"),
        },
        _ => throw new ArgumentException($"not a hosting option: {name}", nameof(name)),
    };

    /// <summary>Least <c>--strategy-memory</c>, MiB.</summary>
    public const int MinimumMemoryMb = 64;

    /// <summary>Most <c>--strategy-memory</c>, MiB (1 TiB).</summary>
    public const int MaximumMemoryMb = 1_048_576;
}
