namespace URWPGSim2D.Protocol;

/// <summary>The server's answer to a hello: what the client plays. Everything in it holds for the whole match.</summary>
/// <param name="Version">The protocol version of the rest of the connection.</param>
/// <param name="Team">The team the client controls (0 or 1).</param>
/// <param name="Item">The item's command-line name (<c>ball-grab</c>), or empty for a plain scene.</param>
/// <param name="ItemName">The item's name as the snapshot gives it (<see cref="MatchSnapshot.ItemName"/>).</param>
/// <param name="Fish">Indices of the fish the client decides for, in the order of its decisions.</param>
/// <param name="FishCount">Fish in every snapshot.</param>
/// <param name="BallCount">Balls in every snapshot.</param>
/// <param name="TotalCycles">Cycles of the match (<see cref="MatchSnapshot.TotalCycles"/>; 0 without an item).</param>
/// <param name="DeadlineMs">The deadline of one cycle's answer, ms.</param>
/// <param name="FieldLength">Field length, mm.</param>
/// <param name="FieldWidth">Field width, mm.</param>
/// <param name="Obstacles">The obstacles (they do not move).</param>
public sealed record AssignmentMessage(
    int Version, int Team, string Item, string ItemName, int[] Fish, int FishCount, int BallCount, int TotalCycles,
    int DeadlineMs, float FieldLength, float FieldWidth, ObstacleView[] Obstacles)
{
    /// <summary>Whether the server records the strategy's debug drawings: the client then sends them in each <c>decisions</c> message's <c>draw</c>.</summary>
    public bool Draw { get; init; }

    /// <summary>Whether the server records what the strategy prints: the client then sends it in each <c>decisions</c> message's <c>log</c>.</summary>
    public bool Log { get; init; }

    /// <summary>Whether every <c>cycle</c> message carries the fish and balls packed (<see cref="PackedCycle"/>): only for a client whose hello asked for it.</summary>
    public bool Packed { get; init; }

    /// <summary>
    /// Whether the server keeps the connection after this match's <c>end</c> for the next match (only for a client
    /// whose hello said <c>"series":true</c>): the client then says hello again and waits for the next assignment.
    /// </summary>
    public bool Series { get; init; }

    /// <summary>A snapshot sized for this match, to be filled by each <c>cycle</c> message.</summary>
    public MatchSnapshot CreateSnapshot() => CreateSnapshotWriter().Snapshot;

    /// <summary>The writer of a new snapshot of the assigned match (<see cref="CreateSnapshot"/>), for the side that fills it.</summary>
    public MatchSnapshotWriter CreateSnapshotWriter() => new(FishCount, BallCount, Obstacles, FieldLength, FieldWidth);
}
