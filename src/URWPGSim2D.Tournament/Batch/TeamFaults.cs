namespace URWPGSim2D.Tournament.Batch;

/// <summary>
/// The faults of one team's strategy in one match, as the result file's <c>faults</c> entries
/// carry them (only strategies that faulted have an entry).
/// </summary>
/// <param name="Team">The team the strategy plays for.</param>
/// <param name="Strategy">The strategy's label (its team name, as the summary shows it).</param>
/// <param name="Exceptions">Calls that threw.</param>
/// <param name="Timeouts">Calls that missed their deadline, or skipped while one was still running.</param>
/// <param name="BadAnswers">Calls that returned null or too few decisions.</param>
/// <param name="First">The first fault: its cycle and message.</param>
/// <param name="Crashes">1 when the strategy's host ended before the match did (results files without the field: 0).</param>
public sealed record TeamFaults(int Team, string Strategy, int Exceptions, int Timeouts, int BadAnswers, string First, int Crashes = 0)
{
    /// <summary>All faults of the strategy.</summary>
    public int Total => Exceptions + Timeouts + BadAnswers + Crashes;
}
