namespace URWPGSim2D.Hosting;

/// <summary>The server failed while it dealt with one team's strategy (its host, its connection): the failure is put on that team.</summary>
/// <param name="team">The team.</param>
/// <param name="inner">What failed.</param>
public sealed class TeamFaultException(int team, Exception inner)
    : Exception($"team {team}: {inner.GetType().Name}: {inner.Message}", inner)
{
    /// <summary>The team at fault.</summary>
    public int Team { get; } = team;
}
