using System;
using System.Globalization;
using System.Text;
using System.Text.Encodings.Web;
using System.Text.Json;

namespace URWPGSim2D.Server.Tournament;

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
/// </summary>
internal static class StandingsJson
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
                var p = standings.Points[k];
                t.Append("    {\"name\": ").Append(Text(p.Name))
                    .Append(Inv($", \"rank\": {p.Rank}, \"played\": {p.Played}, \"won\": {p.Won}, \"drawn\": {p.Drawn}, \"lost\": {p.Lost}, \"goalsFor\": {p.GoalsFor}, \"goalsAgainst\": {p.GoalsAgainst}, \"goalDifference\": {p.GoalDifference}, \"points\": {p.Points}}}"))
                    .Append(k + 1 < standings.Points.Count ? ",\n" : "\n");
            }

            t.Append("  ]");
        }

        t.Append("\n}\n");
        return t.ToString();
    }

    /// <summary>Rounded half away from zero, −0 as 0.</summary>
    public static double Round(double value, int digits) => Math.Round(value, digits, MidpointRounding.AwayFromZero) + 0.0;

    // The shortest text that reads back as the rounded value (1500, 1523.4, 0.125).
    private static string Number(double value, int digits) => Round(value, digits).ToString("R", CultureInfo.InvariantCulture);

    private static string Text(string value) => JsonSerializer.Serialize(value, TournamentJsonContext.Default.String);

    private static string Inv(FormattableString text) => text.ToString(CultureInfo.InvariantCulture);
}
