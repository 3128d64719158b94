namespace URWPGSim2D.Engine.Teams;

/// <summary>
/// Teams whose strategies run in the calling program, on the thread that steps the match, one
/// after another in seat order, with no time limit: what a program that embeds the engine, or the
/// built-in strategies, need. A strategy that throws is charged (<see cref="TeamSeat.ChargeThrown"/>)
/// and its fish keep their last decisions. For deadlines, isolation and other processes, use the
/// server's strategy hosts.
/// </summary>
public sealed class StrategyTeams : IMatchTeams
{
    private readonly StrategySeat[] _seats;

    /// <summary>Creates the teams of these seats, asked in this order.</summary>
    /// <param name="seats">The seats.</param>
    public StrategyTeams(IReadOnlyList<StrategySeat> seats)
    {
        ArgumentNullException.ThrowIfNull(seats);
        _seats = [.. seats];
    }

    /// <inheritdoc/>
    public IReadOnlyList<TeamSeat> Seats => _seats;

    /// <inheritdoc/>
    public void Decide(MatchSnapshot snapshot, FishState[] fish)
    {
        ArgumentNullException.ThrowIfNull(snapshot);
        int cycle = snapshot.Cycle + 1; // the cycle these decisions drive
        foreach (var seat in _seats)
        {
            seat.Decisions.CopyTo(seat.Scratch, 0);
            if (seat.Plays)
            {
                seat.DecideInProcess(seat.Strategy, snapshot, cycle);
            }

            seat.WriteDecisions(fish);
        }
    }

    /// <summary>Whether every seat's strategy can go back to its state at the match's start (built-in strategies).</summary>
    internal bool CanRestart
    {
        get
        {
            foreach (var seat in _seats)
            {
                if (seat.Strategy is not IRestartable)
                {
                    return false;
                }
            }

            return true;
        }
    }

    /// <summary>Every seat and strategy back to its state at the match's start (<see cref="CanRestart"/>).</summary>
    internal void Restart()
    {
        foreach (var seat in _seats)
        {
            seat.Restart();
            ((IRestartable)seat.Strategy).Restart();
        }
    }

    /// <inheritdoc/>
    public void Stop(int cycles, IReadOnlyList<int> goals)
    {
    }
}
