namespace URWPGSim2D.Tournament;

/// <summary>
/// One line of a tournament's result file after the header: a played match (the batch result
/// format plus its entrants) or a forfeit (an entrant of the match could not be loaded).
/// </summary>
/// <param name="Index">The match's index in the schedule.</param>
/// <param name="Seed">Its seed.</param>
/// <param name="Entrants">Per team, the entrant's name.</param>
/// <param name="Result">The match's result, or null for a forfeit.</param>
/// <param name="Forfeits">For a forfeit, the teams whose entrant could not be loaded (empty for a played match).</param>
/// <param name="Reasons">For a forfeit, per forfeiting team (as <paramref name="Forfeits"/>), the one-line reason its entrant could not be loaded.</param>
/// <param name="Failed">For a forfeit, true when the match failed inside the server (the teams at fault forfeit; a re-run keeps the record instead of failing again).</param>
public sealed record TournamentRecord(int Index, ulong Seed, IReadOnlyList<string> Entrants, MatchResult? Result, IReadOnlyList<int> Forfeits, IReadOnlyList<string> Reasons, bool Failed = false)
{
    /// <summary>Whether the match was forfeited rather than played.</summary>
    public bool IsForfeit => Result is null;
}
