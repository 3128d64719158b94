using System;
using System.Collections.Generic;
using System.Linq;

namespace URWPGSim2D.Server.Tournament;

/// <summary>
/// The points table of a two-team tournament, as a class or a league keeps it beside the ratings:
/// 3 points a win, 1 a draw, 0 a loss (the item's referee decides, as for the ratings; a forfeit is
/// a loss of the side that could not play, without goals); ranked by points, then goal difference,
/// then goals scored (the item's score per match), then the points of the matches between the
/// entrants still level (head to head), then the name.
/// </summary>
internal static class PointsTable
{
    /// <summary>One entrant's line.</summary>
    /// <param name="Entrant">The entrant's index.</param>
    /// <param name="Name">Its name.</param>
    /// <param name="Rank">Its place, 1 first.</param>
    /// <param name="Played">Matches counted.</param>
    /// <param name="Wins">Wins.</param>
    /// <param name="Draws">Draws.</param>
    /// <param name="Losses">Losses.</param>
    /// <param name="GoalsFor">Its score summed over its matches.</param>
    /// <param name="GoalsAgainst">Its opponents' scores summed.</param>
    /// <param name="Points">3 a win, 1 a draw.</param>
    internal sealed record Line(int Entrant, string Name, int Rank, int Played, int Wins, int Draws, int Losses, int GoalsFor, int GoalsAgainst, int Points)
    {
        /// <summary>Goals for minus goals against.</summary>
        public int Difference => GoalsFor - GoalsAgainst;
    }

    /// <summary>The table of a two-team tournament's standings, by rank; empty for other items.</summary>
    public static List<Line> Of(Standings s)
    {
        if (s.Teams != 2)
        {
            return [];
        }

        int n = s.Header.Entrants.Count;
        var index = new Dictionary<string, int>(StringComparer.Ordinal);
        for (int i = 0; i < n; i++)
        {
            index[s.Header.Entrants[i].Name] = i;
        }

        var w = new int[n];
        var d = new int[n];
        var l = new int[n];
        var goalsFor = new int[n];
        var against = new int[n];
        var pairPoints = new int[n, n]; // points of i in its matches against j
        foreach (var r in s.Records)
        {
            if (r.Entrants.Count != 2 || !index.TryGetValue(r.Entrants[0], out int a) || !index.TryGetValue(r.Entrants[1], out int b))
            {
                continue;
            }

            double? score = r.Result is { } result
                ? (result.Winner == 0 ? 1 : result.Winner == 1 ? 0 : 0.5)
                : r.Forfeits.Contains(0) == r.Forfeits.Contains(1) ? null : r.Forfeits.Contains(0) ? 0 : 1;
            if (score is not { } x)
            {
                continue;
            }

            if (r.Result is { } played)
            {
                int[] scores = played.Scores is { Length: 2 } sc ? sc : [played.Goals0, played.Goals1];
                goalsFor[a] += scores[0];
                against[a] += scores[1];
                goalsFor[b] += scores[1];
                against[b] += scores[0];
            }

            Count(a, b, x);
            Count(b, a, 1 - x);
        }

        void Count(int i, int j, double x)
        {
            if (x == 1)
            {
                w[i]++;
                pairPoints[i, j] += 3;
            }
            else if (x == 0)
            {
                l[i]++;
            }
            else
            {
                d[i]++;
                pairPoints[i, j] += 1;
            }
        }

        var lines = Enumerable.Range(0, n)
            .Select(i => new Line(i, s.Header.Entrants[i].Name, 0, w[i] + d[i] + l[i], w[i], d[i], l[i], goalsFor[i], against[i], (3 * w[i]) + d[i]))
            .ToList();

        // Points, goal difference, goals; then, within each group still level, head to head; then the name.
        var ordered = new List<Line>(n);
        foreach (var group in lines.GroupBy(x => (x.Points, x.Difference, x.GoalsFor)).OrderByDescending(g => g.Key.Points).ThenByDescending(g => g.Key.Difference).ThenByDescending(g => g.Key.GoalsFor))
        {
            var members = group.Select(x => x.Entrant).ToList();
            ordered.AddRange(group.OrderByDescending(x => members.Sum(j => pairPoints[x.Entrant, j])).ThenBy(x => x.Name, StringComparer.Ordinal));
        }

        return [.. ordered.Select((x, k) => x with { Rank = k + 1 })];
    }
}
