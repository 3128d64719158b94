namespace URWPGSim2D.Hosting;

/// <summary>
/// The byte transport under one <see cref="StrategyConnection"/>: the pipes of a strategy host
/// process (<see cref="HostProcess"/>) or a remote client's TCP connection (<see cref="TcpLink"/>).
/// The protocol above it is the same for both.
/// </summary>
internal interface IStrategyLink : IDisposable
{
    /// <summary>The stream from the client (a host's standard output, a socket).</summary>
    Stream FromClient { get; }

    /// <summary>The stream to the client.</summary>
    Stream ToClient { get; }

    /// <summary>
    /// Whether a wait that runs out (<see cref="BeginWait"/>) is a late answer the link survives: the
    /// read throws <see cref="TimeoutException"/> and the answer may still come (TCP). When false, the
    /// link is cut instead (a host process is killed) and the read ends the stream.
    /// </summary>
    bool SurvivesLateAnswer { get; }

    /// <summary>Limits the reads until <see cref="EndWait"/> to <paramref name="limit"/> of wall time from now.</summary>
    void BeginWait(TimeSpan limit);

    /// <summary>Lifts the limit of <see cref="BeginWait"/>.</summary>
    void EndWait();

    /// <summary>Whether the link was cut because a wait ran out (<see cref="BeginWait"/>; a host killed by the watchdog).</summary>
    bool CutByWait { get; }

    /// <summary>
    /// The CPU time the client's processes have used so far (a host in a control group: every thread
    /// and child process of its sandbox), or null where it is not measured (a remote client, a host
    /// without a control group).
    /// </summary>
    TimeSpan? CpuTime();

    /// <summary>How long so far some process of the client's sandbox was ready to run but waited for a CPU (a busy machine), or null where it is not measured.</summary>
    TimeSpan? WaitingTime();

    /// <summary>The most memory the client's sandbox has held at once so far, bytes (a host in a control group), or null where it is not measured.</summary>
    long? PeakMemoryBytes();

    /// <summary>Cuts the link at once (kills the host, closes the socket).</summary>
    void Abort();

    /// <summary>Gives the client up to <paramref name="ms"/> to go after the match's end.</summary>
    void Finish(int ms);

    /// <summary>How the link ended, for the fault report.</summary>
    string Ending();
}
