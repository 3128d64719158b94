namespace URWPGSim2D.Tournament.Batch;

/// <summary>
/// The first line of a result file: which batch it belongs to and which share of it this file
/// holds. Shards of one batch have equal headers but for <see cref="ShardIndex"/>.
/// </summary>
/// <param name="Scene">The scene: <c>default</c>, <c>crowd N</c>, or <c>file NAME sha256 HEX</c>.</param>
/// <param name="Strategies">Strategy assemblies replacing a team's (<c>0=PATH</c>, <c>;</c>-separated), or empty.</param>
/// <param name="Teams">The two teams' strategy labels.</param>
/// <param name="Noise">Noise override: <c>on</c>, <c>off</c> or <c>scenario</c>.</param>
/// <param name="StrategyTimeoutMs">Time limit of loaded strategies, ms.</param>
/// <param name="FirstSeed">Seed of match 0 (match j uses FirstSeed + j).</param>
/// <param name="Matches">Matches in the whole batch.</param>
/// <param name="Cycles">Cycles per match.</param>
/// <param name="ShardIndex">This file's shard, 0 … ShardCount − 1: the matches j with j mod ShardCount = ShardIndex.</param>
/// <param name="ShardCount">Shards the batch is split into.</param>
public sealed record BatchHeader(
    string Scene, string Strategies, string Teams, string Noise, int StrategyTimeoutMs, ulong FirstSeed,
    int Matches, int Cycles, int ShardIndex, int ShardCount)
{
    /// <summary>Whether match <paramref name="index"/> belongs to this shard.</summary>
    public bool Holds(int index) => index % ShardCount == ShardIndex;

    /// <summary>Number of matches in this shard.</summary>
    public int ShardMatches => (Matches / ShardCount) + (ShardIndex < Matches % ShardCount ? 1 : 0);

    /// <summary>The same batch as a single shard (what merging all shards gives).</summary>
    public BatchHeader Whole => this with { ShardIndex = 0, ShardCount = 1 };

    /// <summary>What differs between the headers of two batches, e.g. <c>first seed 1 vs 1001</c> (the first difference found).</summary>
    public static string Difference(BatchHeader a, BatchHeader b) =>
        a.Scene != b.Scene ? $"scene {a.Scene} vs {b.Scene}"
        : a.Matches != b.Matches ? $"{a.Matches} vs {b.Matches} matches"
        : a.FirstSeed != b.FirstSeed ? $"first seed {a.FirstSeed} vs {b.FirstSeed}"
        : a.Cycles != b.Cycles ? $"{a.Cycles} vs {b.Cycles} cycles"
        : "strategies, noise or time limit differ";
}
