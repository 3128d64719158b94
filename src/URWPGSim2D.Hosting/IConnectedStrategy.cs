using URWPGSim2D.Protocol;

namespace URWPGSim2D.Hosting;

/// <summary>A team's strategy that plays over the strategy protocol: in a strategy host process or on a remote client.</summary>
internal interface IConnectedStrategy : IDisposable
{
    /// <summary>The team name the client said hello with, or null.</summary>
    string? TeamName { get; }

    /// <summary>How the connection ended when the last call's <see cref="ConnectionOutcome.BadAnswer"/> also ended it (an overlong line), else null.</summary>
    string? EndedBy { get; }

    /// <summary>Whether another client may take over after the connection ends (a remote team), rather than the team's strategy ending for the match (a host).</summary>
    bool Reconnects { get; }

    /// <summary>The debug drawings the client sent with the last call's answer (decided or an exception), or null when they are not recorded.</summary>
    DebugRecorder? Drawings { get; }

    /// <summary>What the client's strategy printed, sent with the last call's answer (decided or an exception), or null when it is not recorded.</summary>
    StrategyLog? Log { get; }

    /// <summary>
    /// Sends <paramref name="snapshot"/> and reads the cycle's decisions into <paramref name="decisions"/>
    /// (written only on <see cref="ConnectionOutcome.Decided"/>). <paramref name="message"/> says what went wrong otherwise.
    /// </summary>
    /// <param name="snapshot">What the strategy sees.</param>
    /// <param name="decisions">Where the decisions go.</param>
    /// <param name="waitLimit">Wall time the server waits for the answer (then <see cref="ConnectionOutcome.GivenUp"/>).</param>
    /// <param name="message">What went wrong, or null.</param>
    ConnectionOutcome Decide(MatchSnapshot snapshot, Span<Decision> decisions, TimeSpan waitLimit, out string? message);

    /// <summary>The CPU time the client's processes have used so far, or null where it is not measured (<see cref="IStrategyLink.CpuTime"/>).</summary>
    TimeSpan? CpuTime();

    /// <summary>How long so far the client's processes waited for a CPU, or null where it is not measured (<see cref="IStrategyLink.WaitingTime"/>).</summary>
    TimeSpan? WaitingTime();

    /// <summary>The most memory the client's sandbox has held at once so far, bytes, or null where it is not measured (<see cref="IStrategyLink.PeakMemoryBytes"/>).</summary>
    long? PeakMemoryBytes();

    /// <summary>Sends the end of the match to a client still there, lets it go, and disposes the connection.</summary>
    void Stop(EndMessage end);
}
