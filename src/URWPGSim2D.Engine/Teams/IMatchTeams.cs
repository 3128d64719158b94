namespace URWPGSim2D.Engine.Teams;

/// <summary>
/// Who decides for a match's fish: asked once a cycle with the snapshot of the last cycle, it writes
/// every fish's decision; told when the match ends. The match engine knows its teams only through
/// this and their seats (<see cref="TeamSeat"/>): how strategies are run, timed and isolated is the
/// implementation's business.
/// </summary>
public interface IMatchTeams
{
    /// <summary>Each strategy's seat, in decision order: its team, its name and what it did wrong, drew or printed.</summary>
    IReadOnlyList<TeamSeat> Seats { get; }

    /// <summary>Writes every fish's decision for the next cycle.</summary>
    /// <param name="snapshot">What the strategies see: the last cycle.</param>
    /// <param name="fish">The fish; each one's <see cref="FishState.Decision"/> is set.</param>
    void Decide(MatchSnapshot snapshot, FishState[] fish);

    /// <summary>Ends the strategies after the match (idempotent), telling them the cycles played and the final score.</summary>
    /// <param name="cycles">Cycles played.</param>
    /// <param name="goals">Each team's final score (the item's, else the goals).</param>
    void Stop(int cycles, IReadOnlyList<int> goals);

    /// <summary>Ends the strategies of a match never played (cycle 0, no goals).</summary>
    void Stop() => Stop(0, [0, 0]);

    /// <summary>The labels of the strategies playing for <paramref name="team"/>, joined with "+" ("no fish" for a team without fish).</summary>
    /// <param name="team">The team.</param>
    string TeamLabel(int team)
    {
        var labels = new List<string>();
        foreach (var seat in Seats)
        {
            if (seat.Team == team && !labels.Contains(seat.Label))
            {
                labels.Add(seat.Label);
            }
        }

        return labels.Count == 0 ? "no fish" : string.Join("+", labels);
    }
}
