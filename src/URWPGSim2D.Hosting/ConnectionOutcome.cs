namespace URWPGSim2D.Hosting;

/// <summary>What one cycle's call of a strategy in another process (a host or a remote client) came to.</summary>
internal enum ConnectionOutcome
{
    /// <summary>Decisions for every fish.</summary>
    Decided,

    /// <summary>The strategy threw.</summary>
    Exception,

    /// <summary>The strategy answered something unusable, or the client broke the protocol for this cycle.</summary>
    BadAnswer,

    /// <summary>The client reported that its strategy missed its deadline (or is still busy).</summary>
    TimedOut,

    /// <summary>No answer within the time the server waited: a host is killed then; a remote client's answer, should it come, is skipped.</summary>
    GivenUp,

    /// <summary>The strategy host ended (crashed, exited, was killed) or could not start: no more answers this match.</summary>
    Ended,

    /// <summary>The remote client disconnected (or was cut off) this cycle; a new one may connect.</summary>
    Disconnected,

    /// <summary>No remote client is connected since an earlier disconnect: nothing asked, nothing charged.</summary>
    Absent,
}
