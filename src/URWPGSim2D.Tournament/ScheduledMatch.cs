namespace URWPGSim2D.Tournament;

/// <summary>One match of a tournament's schedule.</summary>
/// <param name="Index">Its number, 0 … matches − 1: the order of the schedule and of the result file.</param>
/// <param name="Seed">The match's seed (the layout's and the noise's).</param>
/// <param name="Sides">Per team (team 0 first), the entrant playing it.</param>
public sealed record ScheduledMatch(int Index, ulong Seed, IReadOnlyList<int> Sides);
