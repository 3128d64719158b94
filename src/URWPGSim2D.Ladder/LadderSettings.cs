using System;
using System.Collections.Generic;
using URWPGSim2D.Hosting;
using URWPGSim2D.Ladder.Play;

namespace URWPGSim2D.Ladder;

/// <summary>How a ladder service runs: <c>urwpgsim2d ladder serve</c>'s options.</summary>
public sealed record LadderSettings
{
    /// <summary>The built-in strategies a house entrant may play: the item's demo, chase-ball, idle.</summary>
    public static IReadOnlyList<string> HouseStrategies { get; } = [Tournament.Entrant.Demo, "chase-ball", "idle"];

    /// <summary>The item of the ladder to create or reopen on start (its slug), or null for the newest ladder (ball-grab when there is none).</summary>
    public string? Item { get; init; }

    /// <summary>Cycles per match of a ladder created now (600 a minute); null keeps a reopened ladder's length (10 minutes for a new one).</summary>
    public int? Cycles { get; init; }

    /// <summary>
    /// The data folder: the SQLite database (unless <see cref="Database"/>) and copies of the submissions and
    /// replay pages the database keeps (a worker's own folder, not the service's).
    /// </summary>
    public string DataDir { get; init; } = "ladder-data";

    /// <summary>A PostgreSQL connection string (<c>Host=…;Database=…</c>), or null for SQLite in <see cref="DataDir"/>.</summary>
    public string? Database { get; init; }

    /// <summary>The port to listen on (0: any free port).</summary>
    public int Port { get; init; } = 5080;

    /// <summary>The address to listen on (loopback unless given).</summary>
    public string Host { get; init; } = "127.0.0.1";

    /// <summary>The organiser's token; null: the stored one, or a new one printed on the first start.</summary>
    public string? AdminToken { get; init; }

    /// <summary>Matches played at once by this process (0: this process plays none, another worker does).</summary>
    public int Workers { get; init; } = 1;

    /// <summary>The shortest takeover time, s: a job's renewals (every fifth of it) stay seconds apart.</summary>
    public const int MinTakeoverSeconds = 10;

    /// <summary>The longest takeover time, s (a day).</summary>
    public const int MaxTakeoverSeconds = 86_400;

    /// <summary>
    /// With PostgreSQL, how long a match taken by a worker that stopped answering waits before another plays
    /// it (whole seconds, <see cref="MinTakeoverSeconds"/> to <see cref="MaxTakeoverSeconds"/>);
    /// null: the one the database keeps (a minute unless set). Kept in the database for the workers.
    /// </summary>
    public TimeSpan? Takeover { get; init; }

    /// <summary>How user strategies run (strategy hosts, sandbox, memory).</summary>
    public HostSettings HostSettings { get; init; } = HostSettings.Default;

    /// <summary>The time limit of a strategy's call, ms.</summary>
    public int StrategyTimeoutMs { get; init; } = MatchBuilder.DefaultStrategyTimeoutMs;

    /// <summary>Upload limits and the default per-day submission limit.</summary>
    public LadderLimits Limits { get; init; } = new();
}
