using System.Collections.Generic;
using System.Linq;
using URWPGSim2D.Ladder.Storage;

namespace URWPGSim2D.Ladder;

/// <summary>
/// A ladder's final round: its teams (each with the submission it plays, 0 for a house entrant), how
/// many matches each pair plays, and how many of its matches are played and in all.
/// </summary>
/// <param name="Teams">Per team id, its submission in the final.</param>
/// <param name="Rounds">Matches of each pair.</param>
/// <param name="Played">Matches finished.</param>
/// <param name="Matches">Matches in all.</param>
internal sealed record FinalRound(IReadOnlyDictionary<long, long> Teams, int Rounds, int Played, int Matches)
{
    /// <summary>The round of these final matches, or null when there are none.</summary>
    public static FinalRound? Of(IReadOnlyList<MatchRow> matches)
    {
        if (matches.Count == 0)
        {
            return null;
        }

        var teams = new Dictionary<long, long>();
        foreach (var m in matches)
        {
            teams.TryAdd(m.Teams[0], m.Submissions[0]);
            teams.TryAdd(m.Teams[1], m.Submissions[1]);
        }

        int pairs = teams.Count * (teams.Count - 1) / 2;
        return new FinalRound(teams, matches.Count / pairs, matches.Count(m => m.State == MatchRow.Done), matches.Count);
    }
}
