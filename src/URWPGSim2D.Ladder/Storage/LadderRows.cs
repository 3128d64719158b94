using System;
using System.Collections.Generic;

namespace URWPGSim2D.Ladder.Storage;

/// <summary>A ladder: one item, its match length and first seed, whether ranked play is paused.</summary>
internal sealed record LadderRow(long Id, string Item, int Cycles, ulong FirstSeed, bool Paused, DateTime Created);

/// <summary>
/// A team: its unique name, the hash of its token, its password hash (or null) and, for a house
/// entrant, its built-in strategy and the ladder it plays in (<paramref name="LadderId"/>; 0 for a
/// team that submits its own strategies, which plays in every ladder it has a working submission of).
/// </summary>
internal sealed record TeamRow(long Id, string Name, string TokenHash, string? PasswordHash, string? House, DateTime Created, long LadderId = 0);

/// <summary>One upload of a team for one ladder: where its files are, how it is loaded, whether it compiled and checked, and the log of that.</summary>
internal sealed record SubmissionRow(long Id, long TeamId, DateTime Created, string Kind, string Path, string State, string Log, long LadderId = 0)
{
    /// <summary>Being checked.</summary>
    public const string Checking = "checking";

    /// <summary>Compiled and checked: it may play.</summary>
    public const string Ok = "ok";

    /// <summary>It did not compile or check (the log says why).</summary>
    public const string Error = "error";
}

/// <summary>
/// One ranked match: its seed, the two teams and the submission each played with (0 for a house
/// entrant), its state (queued, running, done), and once done the tournament record line and whether
/// a replay page was written.
/// </summary>
internal sealed record MatchRow(
    long Id, long LadderId, ulong Seed, IReadOnlyList<long> Teams, IReadOnlyList<long> Submissions, string State,
    DateTime Created, DateTime? Started, DateTime? Finished, string? Record, bool Final)
{
    /// <summary>Waiting for a worker.</summary>
    public const string Queued = "queued";

    /// <summary>Being played.</summary>
    public const string Running = "running";

    /// <summary>Played; its record is written.</summary>
    public const string Done = "done";
}
