namespace URWPGSim2D.Tournament;

/// <summary>
/// DIR/standings.csv and DIR/matches.csv for a spreadsheet: comma-separated, a header line, fields
/// with a comma, a quote or a line break quoted (RFC 4180), UTF-8 with a byte-order mark (so a
/// spreadsheet shows Chinese names as they are), one line per entrant in rank order or per match in
/// index order. A text field (a name, a reason) that a spreadsheet would take for a formula
/// (it starts with <c>=</c>, <c>+</c>, <c>-</c>, <c>@</c>, a tab or a carriage return) starts with <c>'</c>.
/// A group stage and knockout adds columns at the end: <c>group,group_rank,reached</c> to the standings
/// (<see cref="Bracket.Reached"/>) and <c>stage,round</c> to the matches (<c>group</c> and the group's name, or
/// <c>knockout</c> and the round's name).
/// </summary>
internal static class StandingsCsv
{
    /// <summary>The standings file's text: per entrant its rating (or mean score) line, its points-table line and its runtime faults.</summary>
    /// <param name="s">The standings.</param>
    public static string Standings(Standings s)
    {
        var t = new StringBuilder("\uFEFF");
        bool one = s.Teams == 1;
        t.Append(one
            ? "rank,entrant,score,ci_low,ci_high,played,seconds,exceptions,timeouts,bad_answers,host_ends,error\r\n"
            : "rank,entrant,rating,ci_low,ci_high,played,wins,draws,losses,points_rank,points,goals_for,goals_against,goal_difference,exceptions,timeouts,bad_answers,host_ends,error" + (s.Cup is null ? "\r\n" : ",group,group_rank,reached\r\n"));
        var points = s.Points.ToDictionary(p => p.Entrant);
        foreach (var r in s.Rows)
        {
            var fields = new List<string>
            {
                Int(r.Rank), Text(r.Name), StandingsText.Value(s, r.Rating), StandingsText.Value(s, r.Interval.Low), StandingsText.Value(s, r.Interval.High), Int(r.Played),
            };
            if (one)
            {
                fields.Add(StandingsJson.Round(r.Seconds, 1).ToString("0.0", CultureInfo.InvariantCulture));
            }
            else
            {
                var p = points[r.Entrant];
                fields.AddRange([Int(r.Wins), Int(r.Draws), Int(r.Losses), Int(p.Rank), Int(p.Points), Int(p.GoalsFor), Int(p.GoalsAgainst), Int(p.GoalDifference)]);
            }

            var f = r.Faults;
            fields.AddRange([Int(f?.Exceptions ?? 0), Int(f?.Timeouts ?? 0), Int(f?.BadAnswers ?? 0), Int(f?.HostEnds ?? 0), r.Error is null ? string.Empty : Text(StandingsText.Line(r.Error))]);
            if (s.Cup is { } cup)
            {
                var group = cup.Groups.FirstOrDefault(g => g.Entrants.Contains(r.Entrant));
                fields.AddRange([group?.Name ?? string.Empty, group is null ? string.Empty : Int(group.Table.First(p => p.Entrant == r.Entrant).Rank), cup.Reached(r.Entrant)]);
            }

            Line(t, fields);
        }

        return t.ToString();
    }

    /// <summary>The matches file's text: per match its seed, entrants by team, scores, winner, how it was decided, and who forfeited.</summary>
    /// <param name="s">The standings.</param>
    public static string Matches(Standings s)
    {
        var t = new StringBuilder("\uFEFF");
        var header = new List<string> { "match", "seed" };
        header.AddRange(Enumerable.Range(0, s.Teams).Select(k => "team_" + Int(k)));
        header.AddRange(Enumerable.Range(0, s.Teams).Select(k => "score_" + Int(k)));
        header.AddRange(["winner", "result", "forfeited"]);
        if (s.Cup is not null)
        {
            header.AddRange(["stage", "round"]);
        }

        Line(t, header);
        foreach (var m in s.Records)
        {
            var fields = new List<string> { Int(m.Index), m.Seed.ToString(CultureInfo.InvariantCulture) };
            for (int k = 0; k < s.Teams; k++)
            {
                fields.Add(k < m.Entrants.Count ? Text(m.Entrants[k]) : string.Empty);
            }

            int[] scores = m.Result is { } r ? r.Scores ?? [r.Goals0, r.Goals1] : [];
            for (int k = 0; k < s.Teams; k++)
            {
                fields.Add(k < scores.Length ? Int(scores[k]) : string.Empty);
            }

            if (m.Result is { } result)
            {
                fields.Add(result.Winner >= 0 && result.Winner < m.Entrants.Count ? Text(m.Entrants[result.Winner]) : string.Empty);
                fields.Add(Text(result.Rule ?? string.Empty));
                fields.Add(string.Empty);
            }
            else
            {
                fields.Add(string.Empty);
                fields.Add(m.Failed ? "failed" : "forfeit");
                fields.Add(Text(string.Join(";", m.Forfeits.Select(k => m.Entrants[k]))));
            }

            if (s.Cup is { } cup)
            {
                var (stage, round) = cup.Stages.TryGetValue(m.Index, out var x) ? x : (string.Empty, string.Empty);
                fields.AddRange([stage, round]);
            }

            Line(t, fields);
        }

        return t.ToString();
    }

    private static void Line(StringBuilder t, IReadOnlyList<string> fields)
    {
        for (int k = 0; k < fields.Count; k++)
        {
            t.Append(k == 0 ? string.Empty : ",").Append(Field(fields[k]));
        }

        t.Append("\r\n");
    }

    // A field as RFC 4180 writes it: quoted, its quotes doubled, when it holds a comma, a quote or a line break.
    private static string Field(string text) =>
        text.AsSpan().IndexOfAny(",\"\r\n") < 0 ? text : "\"" + text.Replace("\"", "\"\"", StringComparison.Ordinal) + "\"";

    // A text field a spreadsheet never evaluates as a formula.
    private static string Text(string text) => text.Length > 0 && text[0] is '=' or '+' or '-' or '@' or '\t' or '\r' ? "'" + text : text;

    private static string Int(int value) => value.ToString(CultureInfo.InvariantCulture);
}
