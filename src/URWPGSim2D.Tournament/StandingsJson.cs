using System.Text.Encodings.Web;
using System.Text.Json;

namespace URWPGSim2D.Tournament;

/// <summary>
/// DIR/standings.json: <c>{"item": …, "matches": N, "entrants": [{"name", "rank", "rating", "ci": [lo, hi],
/// "played", "wins", "draws", "losses"}, …]}</c> sorted by rank, one entrant a line; for a one-team
/// item each entrant has <c>"score"</c> (the mean score), <c>"ci"</c> (its interval), <c>"played"</c>
/// and <c>"seconds"</c> (the mean match length, the time tie-break) instead of the rating and wins,
/// draws and losses. An entrant that could not be loaded has <c>"error"</c>, its one-line reason, at
/// the end. An entrant whose strategy had runtime faults has <c>"faults"</c> before it:
/// <c>{"exceptions", "timeouts", "badAnswers", "hostEnds", "matches", "first": {"match", "cycle", "text"[, "replay"]}}</c>
/// (<c>cycle</c> absent when not known; <c>replay</c>, the link to that cycle of the match's replay page
/// relative to the folder, only when the page exists). Ratings and their intervals are rounded to 0.1, scores to 0.001, seconds to 0.1.
/// An item of two or more teams also has <c>"points"</c>, the points table (<see cref="PointsTable"/>), best first:
/// <c>[{"name", "rank", "played", "won", "drawn", "lost", "goalsFor", "goalsAgainst", "goalDifference", "points"}, …]</c>.
/// A group stage and knockout (<see cref="Standings.Cup"/>) adds <c>"groups"</c> (each group's name and points table)
/// and <c>"knockout"</c> (<c>{"rounds": [{"name", "pairs": [{"entrants", "from", "seeded", "matches": [{"match", "seed",
/// "teams", "score", "winner"}], "wins", "goals", "winner", "decidedBy"}]}], "champion"}</c>).
/// </summary>
public static class StandingsJson
{
    /// <summary>The file's text.</summary>
    /// <param name="standings">The standings.</param>
    /// <param name="hasReplay">Whether match J's replay page exists (then the first fault gives its link).</param>
    public static string Format(Standings standings, Func<int, bool>? hasReplay = null)
    {
        var t = new StringBuilder();
        t.Append("{\n  \"item\": ").Append(Text(standings.Header.Item))
            .Append(",\n  \"matches\": ").Append(standings.Records.Count.ToString(CultureInfo.InvariantCulture))
            .Append(",\n  \"entrants\": [\n");
        bool one = standings.Teams == 1;
        int digits = one ? 3 : 1;
        for (int k = 0; k < standings.Rows.Count; k++)
        {
            var r = standings.Rows[k];
            t.Append("    {\"name\": ").Append(Text(r.Name)).Append(Inv($", \"rank\": {r.Rank}, "))
                .Append(one ? "\"score\": " : "\"rating\": ").Append(Number(r.Rating, digits))
                .Append(", \"ci\": [").Append(Number(r.Interval.Low, digits)).Append(", ").Append(Number(r.Interval.High, digits)).Append(']')
                .Append(Inv($", \"played\": {r.Played}"));
            t.Append(one ? ", \"seconds\": " + Number(r.Seconds, 1) : Inv($", \"wins\": {r.Wins}, \"draws\": {r.Draws}, \"losses\": {r.Losses}"));
            if (r.Faults is { } f)
            {
                t.Append(Inv($", \"faults\": {{\"exceptions\": {f.Exceptions}, \"timeouts\": {f.Timeouts}, \"badAnswers\": {f.BadAnswers}, \"hostEnds\": {f.HostEnds}, \"matches\": {f.Matches}, \"first\": {{\"match\": {f.FirstMatch}"));
                if (f.FirstCycle is { } cycle)
                {
                    t.Append(Inv($", \"cycle\": {cycle}"));
                }

                t.Append(", \"text\": ").Append(Text(f.FirstText));
                if (hasReplay?.Invoke(f.FirstMatch) == true)
                {
                    t.Append(", \"replay\": ").Append(Text(f.ReplayLink()));
                }

                t.Append("}}");
            }

            if (r.Error is not null)
            {
                t.Append(", \"error\": ").Append(Text(r.Error));
            }

            t.Append(k + 1 < standings.Rows.Count ? "},\n" : "}\n");
        }

        t.Append("  ]");
        if (standings.Points.Count > 0)
        {
            t.Append(",\n  \"points\": [\n");
            for (int k = 0; k < standings.Points.Count; k++)
            {
                t.Append("    ").Append(PointsLine(standings.Points[k])).Append(k + 1 < standings.Points.Count ? ",\n" : "\n");
            }

            t.Append("  ]");
        }

        if (standings.Cup is { } cup)
        {
            Cup(t, standings, cup);
        }

        t.Append("\n}\n");
        return t.ToString();
    }

    // A line of a points table.
    private static string PointsLine(PointsRow p) =>
        "{\"name\": " + Text(p.Name)
        + Inv($", \"rank\": {p.Rank}, \"played\": {p.Played}, \"won\": {p.Won}, \"drawn\": {p.Drawn}, \"lost\": {p.Lost}, \"goalsFor\": {p.GoalsFor}, \"goalsAgainst\": {p.GoalsAgainst}, \"goalDifference\": {p.GoalDifference}, \"points\": {p.Points}}}");

    // "groups": each group's points table; "knockout": the bracket's rounds, pairs, their matches and winners, and the champion.
    private static void Cup(StringBuilder t, Standings s, Bracket cup)
    {
        string Name(int entrant) => Text(s.Header.Entrants[entrant].Name);
        t.Append(",\n  \"groups\": [\n");
        for (int g = 0; g < cup.Groups.Count; g++)
        {
            var group = cup.Groups[g];
            t.Append("    {\"name\": ").Append(Text(group.Name)).Append(", \"points\": [\n");
            for (int k = 0; k < group.Table.Count; k++)
            {
                t.Append("      ").Append(PointsLine(group.Table[k])).Append(k + 1 < group.Table.Count ? ",\n" : "\n");
            }

            t.Append(g + 1 < cup.Groups.Count ? "    ]},\n" : "    ]}\n");
        }

        t.Append("  ],\n  \"knockout\": {\n    \"rounds\": [\n");
        for (int r = 0; r < cup.Rounds.Count; r++)
        {
            var round = cup.Rounds[r];
            t.Append("      {\"name\": ").Append(Text(round.Name)).Append(", \"pairs\": [\n");
            for (int k = 0; k < round.Ties.Count; k++)
            {
                var tie = round.Ties[k];
                string Side(CupSlot? x) => x is null ? "null" : Name(x.Entrant);
                string From(CupSlot? x) => x is null ? "null" : Text(x.From);
                string Seeded(CupSlot? x) => x is null ? "null" : x.Seed.ToString(CultureInfo.InvariantCulture);
                t.Append("        {\"entrants\": [").Append(Side(tie.A)).Append(", ").Append(Side(tie.B))
                    .Append("], \"from\": [").Append(From(tie.A)).Append(", ").Append(From(tie.B))
                    .Append("], \"seeded\": [").Append(Seeded(tie.A)).Append(", ").Append(Seeded(tie.B)).Append("], \"matches\": [");
                for (int j = 0; j < tie.Matches.Count; j++)
                {
                    var m = tie.Matches[j];
                    t.Append(j == 0 ? string.Empty : ", ").Append(Inv($"{{\"match\": {m.Index}, \"seed\": {m.Seed}, \"teams\": [")).Append(Name(m.Sides[0])).Append(", ").Append(Name(m.Sides[1])).Append(']');
                    if (cup.Records.TryGetValue(m.Index, out var record))
                    {
                        if (record.Result is { } result)
                        {
                            t.Append(Inv($", \"score\": [{GroupsKnockout.Goals(record, 0)}, {GroupsKnockout.Goals(record, 1)}]"));
                            t.Append(", \"winner\": ").Append(result.Winner is 0 or 1 ? Text(record.Entrants[result.Winner]) : "null");
                        }
                        else
                        {
                            t.Append(", \"forfeit\": [").Append(string.Join(", ", record.Forfeits.Select(f => Text(record.Entrants[f])))).Append(']');
                        }
                    }

                    t.Append('}');
                }

                t.Append(Inv($"], \"wins\": [{tie.WinsA}, {tie.WinsB}], \"goals\": [{tie.GoalsA}, {tie.GoalsB}], \"winner\": "))
                    .Append(tie.Winner is null ? "null" : Name(tie.Winner.Entrant))
                    .Append(", \"decidedBy\": ").Append(tie.DecidedBy is null ? "null" : Text(tie.DecidedBy))
                    .Append(k + 1 < round.Ties.Count ? "},\n" : "}\n");
            }

            t.Append(r + 1 < cup.Rounds.Count ? "      ]},\n" : "      ]}\n");
        }

        t.Append("    ],\n    \"champion\": ").Append(cup.Champion is null ? "null" : Name(cup.Champion.Entrant)).Append("\n  }");
    }

    /// <summary>Rounded half away from zero, −0 as 0.</summary>
    public static double Round(double value, int digits) => Math.Round(value, digits, MidpointRounding.AwayFromZero) + 0.0;

    // The shortest text that reads back as the rounded value (1500, 1523.4, 0.125).
    private static string Number(double value, int digits) => Round(value, digits).ToString("R", CultureInfo.InvariantCulture);

    private static string Text(string value) => JsonSerializer.Serialize(value, TournamentJsonContext.Default.String);

    private static string Inv(FormattableString text) => text.ToString(CultureInfo.InvariantCulture);
}
