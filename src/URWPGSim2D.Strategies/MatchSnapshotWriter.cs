using System.Collections.Generic;

namespace URWPGSim2D.Strategies;

/// <summary>
/// Fills a <see cref="MatchSnapshot"/>: what a program that runs strategies (the engine's match, a
/// protocol client, a host that gives each strategy its own copy) uses to tell them the state of the
/// match. Strategies get only the <see cref="Snapshot"/>, which has no way back to its writer, so
/// they can read it but never change it.
/// </summary>
public sealed class MatchSnapshotWriter
{
    /// <summary>Creates a snapshot of a match with the given bodies and field, and its writer.</summary>
    /// <param name="fishCount">Fish of the match, 0 or more.</param>
    /// <param name="ballCount">Balls of the match, 0 or more.</param>
    /// <param name="obstacles">The match's obstacles (they do not move; the snapshot keeps the array).</param>
    /// <param name="fieldLength">Field length along X, mm.</param>
    /// <param name="fieldWidth">Field width along Z, mm.</param>
    /// <exception cref="ArgumentOutOfRangeException">A count is negative.</exception>
    /// <exception cref="ArgumentNullException"><paramref name="obstacles"/> is null.</exception>
    public MatchSnapshotWriter(int fishCount, int ballCount, ObstacleView[] obstacles, float fieldLength, float fieldWidth)
    {
        ArgumentOutOfRangeException.ThrowIfNegative(fishCount);
        ArgumentOutOfRangeException.ThrowIfNegative(ballCount);
        ArgumentNullException.ThrowIfNull(obstacles);
        Snapshot = new MatchSnapshot(fishCount, ballCount, obstacles, fieldLength, fieldWidth);
    }

    private MatchSnapshotWriter(MatchSnapshot snapshot) => Snapshot = snapshot;

    /// <summary>The snapshot this writer fills; hand it to the strategies.</summary>
    public MatchSnapshot Snapshot { get; }

    /// <summary>The snapshot's fish, to be written in place (index i is fish i).</summary>
    public Span<FishView> Fish => Snapshot.FishBuffer;

    /// <summary>The snapshot's balls, to be written in place (index i is ball i).</summary>
    public Span<BallView> Balls => Snapshot.BallBuffer;

    /// <summary>
    /// A writer of a new snapshot of the same match as <paramref name="source"/> that owns its values
    /// (fish, balls, variables), equal to it now: a strategy that reads the copy on its own thread is
    /// unaffected by later changes to the source.
    /// </summary>
    /// <param name="source">The snapshot to copy.</param>
    /// <returns>The copy's writer.</returns>
    public static MatchSnapshotWriter CopyOf(MatchSnapshot source)
    {
        ArgumentNullException.ThrowIfNull(source);
        return new MatchSnapshotWriter(source.CreateCopy());
    }

    /// <summary>Sets the cycle and each team's score (one entry per team; fewer than two: the rest 0, more than four: ignored).</summary>
    /// <param name="cycle">Cycles completed so far.</param>
    /// <param name="goals">Each team's goals (or points).</param>
    public void SetHeader(int cycle, ReadOnlySpan<int> goals) => Snapshot.SetHeader(cycle, goals);

    /// <summary>Sets what the item tells strategies (kept until set again).</summary>
    /// <param name="itemName">The item's original name, or <c>match</c> for a plain scenario.</param>
    /// <param name="variables">The item's state for strategies (the snapshot keeps the dictionary).</param>
    /// <param name="totalCycles">Cycles the match lasts (0 when not known).</param>
    public void SetItem(string itemName, IReadOnlyDictionary<string, string> variables, int totalCycles)
    {
        ArgumentNullException.ThrowIfNull(itemName);
        ArgumentNullException.ThrowIfNull(variables);
        Snapshot.SetItem(itemName, variables, totalCycles);
    }

    /// <summary>Sets whether the teams have changed sides (half time).</summary>
    /// <param name="swapped">True after the half-time swap.</param>
    public void SetSidesSwapped(bool swapped) => Snapshot.SetSidesSwapped(swapped);

    /// <summary>
    /// Makes the snapshot equal to <paramref name="source"/>, copying its values (the writer of a copy
    /// made by <see cref="CopyOf"/> refreshing it each cycle).
    /// </summary>
    /// <param name="source">A snapshot of the same match: as many fish and balls.</param>
    /// <exception cref="ArgumentException">The source has other counts of fish or balls.</exception>
    public void CopyFrom(MatchSnapshot source)
    {
        ArgumentNullException.ThrowIfNull(source);
        if (source.Fish.Length != Snapshot.Fish.Length || source.Balls.Length != Snapshot.Balls.Length)
        {
            throw new ArgumentException($"source: a snapshot of {source.Fish.Length} fish and {source.Balls.Length} balls cannot be copied into one of {Snapshot.Fish.Length} fish and {Snapshot.Balls.Length} balls", nameof(source));
        }

        Snapshot.CopyFrom(source);
    }
}
