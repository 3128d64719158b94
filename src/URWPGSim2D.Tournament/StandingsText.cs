namespace URWPGSim2D.Tournament;

/// <summary>How the standings' numbers and notes are written in DIR/standings.md and the report.</summary>
public static class StandingsText
{
    /// <summary>The model in one sentence.</summary>
    public static string Method(Standings s) => s.Teams == 1
        ? "Mean score per match (ties: the shorter mean match); 95 % intervals by a bootstrap over each entrant's matches (1,000 replicates, fixed seed)."
        : "Bradley-Terry ratings by maximum likelihood (a draw counts half a win; one virtual draw against a 1500 opponent each) on the Elo scale, 400 points = odds of 10 to 1, mean 1500; 95 % intervals by a bootstrap over each pairing's matches (1,000 replicates, fixed seed)."
            + (s.Teams > 2 ? " A match of more than two teams counts as one game between every two of its sides: the item's winner beats the others, else the higher score wins; Played counts these games." : "");

    /// <summary>How the points table is made, in a few words.</summary>
    public const string PointsRule = "3 points a win, 1 a draw; ties: goal difference, goals scored, head to head, name";

    /// <summary>A goal difference as written: <c>+3</c>, <c>0</c>, <c>-2</c>.</summary>
    public static string Signed(int value) => value > 0 ? "+" + value.ToString(CultureInfo.InvariantCulture) : value.ToString(CultureInfo.InvariantCulture);

    /// <summary>The rating (or mean score) as written.</summary>
    public static string Value(Standings s, double value) =>
        StandingsJson.Round(value, s.Teams == 1 ? 3 : 1).ToString(s.Teams == 1 ? "0.000" : "0.0", CultureInfo.InvariantCulture);

    /// <summary>The interval as written, e.g. <c>1450.2 to 1530.9</c>.</summary>
    public static string Interval(Standings s, Interval i) => Value(s, i.Low) + " to " + Value(s, i.High);

    /// <summary>The ranks overlapping a row, e.g. <c>2, 3</c>, or a dash.</summary>
    public static string Overlaps(StandingsRow row) => row.Overlapping.Count == 0 ? "-" : string.Join(", ", row.Overlapping.Select(r => r.ToString(CultureInfo.InvariantCulture)));

    /// <summary>Groups of consecutive ranks whose intervals chain together by overlaps, e.g. "ranks 1-3", as a sentence, or null when every rank is separated.</summary>
    public static string? Ties(Standings s)
    {
        var groups = new StringBuilder();
        int start = 0;
        var rows = s.Rows;
        for (int k = 1; k <= rows.Count; k++)
        {
            if (k < rows.Count && rows[k].Overlapping.Contains(rows[k - 1].Rank))
            {
                continue;
            }

            if (k - start > 1)
            {
                groups.Append(groups.Length > 0 ? ", " : string.Empty).Append(string.Create(CultureInfo.InvariantCulture, $"{start + 1}-{k}"));
            }

            start = k;
        }

        return groups.Length == 0 ? null : $"Not separated by the results (neighbouring intervals overlap): ranks {groups}.";
    }

    /// <summary>
    /// An entrant's runtime faults in one line: <c>2 exceptions in 1 match; first: match 0, cycle 20:
    /// InvalidOperationException: boom</c> (control characters escaped, long messages cut).
    /// </summary>
    public static string Faults(EntrantFaults f) => $"{f.Counts()}; first: {f.Where()}: {Cut(Engine.Messages.MessageText.Escape(Line(f.FirstText)), 200)}";

    private static string Cut(string text, int max) => text.Length <= max ? text : string.Concat(text.AsSpan(0, max), "…");

    /// <summary>Whether the standings list the entrants' code (some entrant is files, with a version, or remote, with its client's name).</summary>
    public static bool ShowsEntrants(Standings s) => s.Header.Entrants.Any(e => e.Version is not null || e.RemotePort is not null);

    /// <summary>How a knockout pairing is decided, in a few words.</summary>
    public const string KnockoutRule = "both sides of the field on each seed; more wins go on (each match as the item decides it, its tie rules included), then the better goal difference, then a further seed (at most 3), then the better seed";

    /// <summary>A knockout pairing: <c>alpha (A1) v delta (B2)</c>, or <c>alpha (A1), a bye</c>.</summary>
    public static string Pairing(Standings s, CupTie t) =>
        t.A is null || t.B is null ? Slot(s, (t.A ?? t.B)!) + ", a bye" : Slot(s, t.A) + " v " + Slot(s, t.B);

    /// <summary>A pairing's matches seed by seed, each score the first side's goals first: <c>seed 3: 1:0, 0:0; seed 4: 2:1, 0:1</c> (<c>-</c> for a bye, <c>forfeit</c> for a match not played).</summary>
    public static string TieMatches(Bracket cup, CupTie t)
    {
        if (t.A is null || t.B is null)
        {
            return "-";
        }

        var text = new StringBuilder();
        foreach (var seed in t.Matches.GroupBy(m => m.Seed))
        {
            text.Append(text.Length > 0 ? "; " : string.Empty).Append(string.Create(CultureInfo.InvariantCulture, $"seed {seed.Key}: "));
            text.Append(string.Join(", ", seed.Select(m =>
            {
                if (!cup.Records.TryGetValue(m.Index, out var r))
                {
                    return "not played";
                }

                if (r.Result is null)
                {
                    return "forfeit";
                }

                bool aFirst = m.Sides[0] == t.A.Entrant;
                int a = GroupsKnockout.Goals(r, aFirst ? 0 : 1), b = GroupsKnockout.Goals(r, aFirst ? 1 : 0);
                return string.Create(CultureInfo.InvariantCulture, $"{a}:{b}");
            })));
        }

        return text.ToString();
    }

    /// <summary>Two counts as <c>2:1</c>.</summary>
    public static string Pair(int a, int b) => string.Create(CultureInfo.InvariantCulture, $"{a}:{b}");

    /// <summary>Who goes on from a pairing, or a dash while it is not decided.</summary>
    public static string GoesOn(Standings s, CupTie t) => t.Winner is null ? "-" : s.Header.Entrants[t.Winner.Entrant].Name;

    private static string Slot(Standings s, CupSlot slot) => s.Header.Entrants[slot.Entrant].Name + " (" + slot.From + ")";

    /// <summary>One line of a reason: line breaks as spaces.</summary>
    public static string Line(string text) => text.ReplaceLineEndings(" ").Trim();
}
