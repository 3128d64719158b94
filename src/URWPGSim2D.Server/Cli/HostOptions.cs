using System.Collections.Frozen;

namespace URWPGSim2D.Server.Cli;

/// <summary>
/// The options of where user strategies run, the same for <c>run</c> and <c>tournament</c>:
/// <c>--isolation process|none</c>, <c>--sandbox auto|required|off</c>, <c>--strategy-memory MB</c>,
/// <c>--strategy-scratch MB</c>, <c>--strategy-processes N</c>.
/// </summary>
internal static class HostOptions
{
    // The options' names, from their declarations.
    private static readonly FrozenSet<string> Names =
        Declare().SelectMany(t => t.Symbols).OfType<Option>().Select(o => o.Name).ToFrozenSet(StringComparer.Ordinal);

    /// <summary>The options' declarations in a usage line (each optional), new for each command that takes them.</summary>
    public static UsageLine.Term[] Declare() =>
    [
        UsageLine.Optional(CliSyntax.Value("--isolation", "process|none", "where user strategies run", CliCompletions.Fixed("process", "none"))),
        UsageLine.Optional(CliSyntax.Value("--sandbox", "auto|required|off", "whether strategy hosts run in the sandbox", CliCompletions.Fixed("auto", "required", "off"))),
        UsageLine.Optional(CliSyntax.Value("--strategy-memory", "MB", "a strategy host's heap limit")),
        UsageLine.Optional(CliSyntax.Value("--strategy-scratch", "MB", "size of a sandboxed host's scratch folder and /tmp")),
        UsageLine.Optional(CliSyntax.Value("--strategy-processes", "N", "most processes and threads of a host's sandbox")),
    ];

    /// <summary>Whether <paramref name="name"/> is one of these options.</summary>
    public static bool Is(string name) => Names.Contains(name);

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
        "--strategy-scratch" => settings with
        {
            ScratchMb = int.TryParse(value, NumberStyles.None, CultureInfo.InvariantCulture, out int mb) && mb >= 1 && mb <= MaximumScratchMb
                ? mb
                : throw error($"--strategy-scratch must be an integer 1..{MaximumScratchMb}, got {MessageText.Quote(value)}"),
        },
        "--strategy-processes" => settings with
        {
            Processes = int.TryParse(value, NumberStyles.None, CultureInfo.InvariantCulture, out int n) && n >= MinimumProcesses && n <= MaximumProcesses
                ? n
                : throw error($"--strategy-processes must be an integer {MinimumProcesses}..{MaximumProcesses}, got {MessageText.Quote(value)}"),
        },
        _ => throw new ArgumentException($"not a hosting option: {name}", nameof(name)),
    };

    /// <summary>Least <c>--strategy-memory</c>, MiB.</summary>
    public const int MinimumMemoryMb = 64;

    /// <summary>Most <c>--strategy-memory</c>, MiB (1 TiB).</summary>
    public const int MaximumMemoryMb = 1_048_576;

    /// <summary>Most <c>--strategy-scratch</c>, MiB (64 GiB).</summary>
    public const int MaximumScratchMb = 65_536;

    /// <summary>Least <c>--strategy-processes</c>: the runtime of a host needs about 20 threads.</summary>
    public const int MinimumProcesses = 32;

    /// <summary>Most <c>--strategy-processes</c>.</summary>
    public const int MaximumProcesses = 65_536;
}
