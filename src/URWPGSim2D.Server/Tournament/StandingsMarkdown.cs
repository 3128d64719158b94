using System.Globalization;
using System.Text;

namespace URWPGSim2D.Server.Tournament;

/// <summary>DIR/standings.md: the standings as a Markdown table, the method, and which ranks the results do not separate.</summary>
internal static class StandingsMarkdown
{
    /// <summary>The file's text.</summary>
    public static string Format(Standings s)
    {
        var t = new StringBuilder();
        t.Append("# Standings: ").Append(s.Header.Item).Append("\n\n");
        t.Append(string.Create(CultureInfo.InvariantCulture, $"{s.Records.Count} matches, {s.Header.Entrants.Count} entrants, {s.Header.Seeds} seeds from {s.Header.FirstSeed}, {s.Header.Cycles} cycles each.\n"));
        t.Append(StandingsText.Method(s)).Append("\n\n");
        if (s.Teams == 1)
        {
            t.Append("| Rank | Entrant | Mean score | 95 % interval | Played | Mean length (s) | Overlaps ranks |\n");
            t.Append("|---:|---|---:|---|---:|---:|---|\n");
        }
        else
        {
            t.Append("| Rank | Entrant | Rating | 95 % interval | Played | Wins | Draws | Losses | Overlaps ranks |\n");
            t.Append("|---:|---|---:|---|---:|---:|---:|---:|---|\n");
        }

        foreach (var r in s.Rows)
        {
            t.Append(string.Create(CultureInfo.InvariantCulture, $"| {r.Rank} | {Cell(r.Name)}{(r.Error is null ? string.Empty : " (not loaded)")} | {StandingsText.Value(s, r.Rating)} | {StandingsText.Interval(s, r.Interval)} | {r.Played} | "));
            t.Append(s.Teams == 1
                ? string.Create(CultureInfo.InvariantCulture, $"{StandingsJson.Round(r.Seconds, 1):0.0} | ")
                : string.Create(CultureInfo.InvariantCulture, $"{r.Wins} | {r.Draws} | {r.Losses} | "));
            t.Append(StandingsText.Overlaps(r)).Append(" |\n");
        }

        if (StandingsText.Ties(s) is { } ties)
        {
            t.Append('\n').Append(ties).Append('\n');
        }

        bool first = true;
        foreach (var r in s.Rows)
        {
            if (r.Error is not null)
            {
                t.Append(first ? "\nNot loaded (every match forfeited):\n\n" : string.Empty);
                t.Append("- ").Append(Cell(r.Name)).Append(": ").Append(StandingsText.Line(r.Error)).Append('\n');
                first = false;
            }
        }

        return t.ToString();
    }

    private static string Cell(string text) => text.Replace("|", "\\|", System.StringComparison.Ordinal);
}
