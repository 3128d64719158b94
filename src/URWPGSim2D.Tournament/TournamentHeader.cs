namespace URWPGSim2D.Tournament;

/// <summary>
/// The first line of a tournament's result file: what was played (the item, the entrants, seeds,
/// length, time limit) and which shard of the schedule the file holds. Two files belong to the
/// same tournament when their headers are equal but for the shard.
/// </summary>
/// <param name="Item">The item's slug.</param>
/// <param name="Entrants">The entrants, in the order of the command line.</param>
/// <param name="Seeds">Seeds per pairing.</param>
/// <param name="FirstSeed">The first seed.</param>
/// <param name="Cycles">Cycles per match.</param>
/// <param name="StrategyTimeoutMs">Time limit of loaded strategies per call, ms.</param>
/// <param name="Matches">Matches of the whole schedule.</param>
/// <param name="ShardIndex">This file's shard (matches j with j mod ShardCount = ShardIndex).</param>
/// <param name="ShardCount">Shards (1: the whole tournament).</param>
public sealed record TournamentHeader(
    string Item, IReadOnlyList<Entrant> Entrants, int Seeds, ulong FirstSeed, int Cycles, int StrategyTimeoutMs,
    int Matches, int ShardIndex = 0, int ShardCount = 1)
{
    /// <summary>
    /// Whether the two headers play their matches alike (item, seeds, length, time limit), whatever
    /// their entrants: then the matches of the entrants both have, in the same version, are the same matches.
    /// </summary>
    public bool SameSettings(TournamentHeader other) =>
        Item == other.Item && Seeds == other.Seeds && FirstSeed == other.FirstSeed && Cycles == other.Cycles && StrategyTimeoutMs == other.StrategyTimeoutMs;

    /// <summary>Whether the two headers describe the same tournament (shards aside).</summary>
    public bool SameTournament(TournamentHeader other) =>
        Item == other.Item && Entrants.SequenceEqual(other.Entrants) && Seeds == other.Seeds && FirstSeed == other.FirstSeed
        && Cycles == other.Cycles && StrategyTimeoutMs == other.StrategyTimeoutMs && Matches == other.Matches;

    /// <summary>The first difference between two tournaments, in words.</summary>
    public string Difference(TournamentHeader other) =>
        Item != other.Item ? $"item {Item} vs {other.Item}"
        : !Entrants.SequenceEqual(other.Entrants) ? $"entrants {Names(this)} vs {Names(other)}"
        : Seeds != other.Seeds ? $"{Seeds} vs {other.Seeds} seeds"
        : FirstSeed != other.FirstSeed ? $"first seed {FirstSeed} vs {other.FirstSeed}"
        : Cycles != other.Cycles ? $"{Cycles} vs {other.Cycles} cycles"
        : StrategyTimeoutMs != other.StrategyTimeoutMs ? $"strategy time limit {StrategyTimeoutMs} vs {other.StrategyTimeoutMs} ms"
        : "the same tournament";

    private static string Names(TournamentHeader h) => string.Join(",", h.Entrants.Select(e => e.Name + "=" + e.Spec + (e.Version is null ? string.Empty : "@" + e.Version)));
}
