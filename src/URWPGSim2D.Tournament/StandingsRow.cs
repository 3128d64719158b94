namespace URWPGSim2D.Tournament;

/// <summary>One entrant's line of the standings.</summary>
/// <param name="Entrant">The entrant's index on the command line.</param>
/// <param name="Name">Its name.</param>
/// <param name="Rank">Its rank, 1 first.</param>
/// <param name="Rating">Two-team items: the rating; one-team items: the mean score.</param>
/// <param name="Interval">The 95 % interval of <paramref name="Rating"/>.</param>
/// <param name="Played">Matches counted (forfeits included).</param>
/// <param name="Wins">Two-team items: wins (forfeits of the opponent included).</param>
/// <param name="Draws">Two-team items: draws.</param>
/// <param name="Losses">Two-team items: losses (own forfeits included).</param>
/// <param name="Seconds">One-team items: the mean match length, s (the time tie-break).</param>
/// <param name="Error">Why the entrant could not be loaded (it forfeits its matches), or null.</param>
/// <param name="Overlapping">The ranks of the other entrants whose interval overlaps this one's, increasing.</param>
/// <param name="Faults">The runtime faults of its strategy over its matches, or null when it had none.</param>
public sealed record StandingsRow(
    int Entrant, string Name, int Rank, double Rating, Interval Interval, int Played, int Wins, int Draws, int Losses,
    double Seconds, string? Error, IReadOnlyList<int> Overlapping, EntrantFaults? Faults = null);
