namespace URWPGSim2D.Tournament;

/// <summary>DIR/standings.md: the standings as a Markdown table, the method, and which ranks the results do not separate.</summary>
internal static class StandingsMarkdown
{
    /// <summary>The file's text.</summary>
    /// <param name="s">The standings.</param>
    /// <param name="hasReplay">Whether match J's replay page exists (then the first fault links to its cycle there).</param>
    /// <param name="teamNames">Per entrant (header order), the team's own name when known.</param>
    public static string Format(Standings s, System.Func<int, bool>? hasReplay = null, System.Collections.Generic.IReadOnlyList<string?>? teamNames = null)
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

        if (s.Points.Count > 0)
        {
            t.Append("\nPoints table (").Append(StandingsText.PointsRule).Append("):\n\n");
            t.Append("| Rank | Entrant | Played | Won | Drawn | Lost | Goals for | Goals against | Goal difference | Points |\n");
            t.Append("|---:|---|---:|---:|---:|---:|---:|---:|---:|---:|\n");
            foreach (var p in s.Points)
            {
                t.Append(string.Create(CultureInfo.InvariantCulture, $"| {p.Rank} | {Cell(p.Name)} | {p.Played} | {p.Won} | {p.Drawn} | {p.Lost} | {p.GoalsFor} | {p.GoalsAgainst} | {StandingsText.Signed(p.GoalDifference)} | {p.Points} |\n"));
            }
        }

        if (s.Cup is { } cup)
        {
            foreach (var group in cup.Groups)
            {
                t.Append("\nGroup ").Append(group.Name).Append(" (").Append(StandingsText.PointsRule).Append("):\n\n");
                t.Append("| Rank | Entrant | Played | Won | Drawn | Lost | Goals for | Goals against | Goal difference | Points |\n");
                t.Append("|---:|---|---:|---:|---:|---:|---:|---:|---:|---:|\n");
                foreach (var p in group.Table)
                {
                    t.Append(string.Create(CultureInfo.InvariantCulture, $"| {p.Rank} | {Cell(p.Name)} | {p.Played} | {p.Won} | {p.Drawn} | {p.Lost} | {p.GoalsFor} | {p.GoalsAgainst} | {StandingsText.Signed(p.GoalDifference)} | {p.Points} |\n"));
                }
            }

            t.Append("\nKnockout (").Append(StandingsText.KnockoutRule).Append("):\n\n");
            t.Append("| Round | Pairing | Matches (seed: goals, both sides) | Wins | Goals | Goes on | Decided by |\n");
            t.Append("|---|---|---|---:|---:|---|---|\n");
            foreach (var round in cup.Rounds)
            {
                foreach (var tie in round.Ties)
                {
                    bool bye = tie.A is null || tie.B is null;
                    t.Append("| ").Append(round.Name).Append(" | ").Append(Cell(StandingsText.Pairing(s, tie))).Append(" | ").Append(StandingsText.TieMatches(cup, tie))
                        .Append(" | ").Append(bye ? "-" : StandingsText.Pair(tie.WinsA, tie.WinsB)).Append(" | ").Append(bye ? "-" : StandingsText.Pair(tie.GoalsA, tie.GoalsB))
                        .Append(" | ").Append(Cell(StandingsText.GoesOn(s, tie))).Append(" | ").Append(tie.DecidedBy ?? "-").Append(" |\n");
                }
            }

            t.Append("\nChampion: ").Append(cup.Champion is null ? "not decided yet" : Cell(s.Header.Entrants[cup.Champion.Entrant].Name)).Append(".\n");
        }

        if (StandingsText.ShowsEntrants(s))
        {
            t.Append("\nEntrants (the version is a hash of the entrant's files: a new version plays its matches again):\n\n");
            t.Append("| Entrant | Code | Version | Team name |\n|---|---|---|---|\n");
            foreach (var r in s.Rows)
            {
                var e = s.Header.Entrants[r.Entrant];
                string? own = teamNames is not null && r.Entrant < teamNames.Count ? teamNames[r.Entrant] : null;
                t.Append("| ").Append(Cell(r.Name)).Append(" | ").Append(Cell(e.Spec)).Append(" | ").Append(e.Version ?? "-").Append(" | ")
                    .Append(own is null ? "-" : Cell(Engine.Messages.MessageText.Escape(own))).Append(" |\n");
            }
        }

        if (s.AnyFaults)
        {
            t.Append("\nRuntime faults (calls that threw, missed their deadline or answered badly; strategy hosts that ended early):\n\n");
            t.Append("| Entrant | Exceptions | Timeouts | Bad answers | Host ends | Matches | First fault |\n");
            t.Append("|---|---:|---:|---:|---:|---:|---|\n");
            foreach (var r in s.Rows)
            {
                if (r.Faults is not { } f)
                {
                    continue;
                }

                string where = hasReplay?.Invoke(f.FirstMatch) == true ? $"[{f.Where()}]({f.ReplayLink()})" : f.Where();
                t.Append(string.Create(CultureInfo.InvariantCulture, $"| {Cell(r.Name)} | {f.Exceptions} | {f.Timeouts} | {f.BadAnswers} | {f.HostEnds} | {f.Matches} | "))
                    .Append(where).Append(": ").Append(Cell(Engine.Messages.MessageText.Escape(StandingsText.Line(f.FirstText)))).Append(" |\n");
            }
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
