using System.Net;

namespace URWPGSim2D.Tournament;

/// <summary>
/// DIR/report.html: one self-contained page (no script, no outside file but the replay pages it
/// links to): the standings, their intervals as an inline SVG plot, the win/draw/loss matrix
/// (two-team items), and every match with its entrants, score, winner and deciding rule, linked to
/// its replay page (<c>replays/match-J.html</c>) when that page exists; a group stage and knockout adds each
/// group's table and the bracket, a column per round.
/// </summary>
internal static class ReportPage
{
    /// <summary>The page's text.</summary>
    /// <param name="s">The standings.</param>
    /// <param name="hasReplay">Whether match J's replay page exists.</param>
    /// <param name="teamNames">Per entrant (header order), the team's own name when known.</param>
    public static string Format(Standings s, Func<int, bool> hasReplay, IReadOnlyList<string?>? teamNames = null)
    {
        var h = new StringBuilder();
        string title = "Tournament: " + s.Header.Item;
        h.Append("<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<title>").Append(E(title)).Append("</title>\n");
        h.Append("<style>body{font-family:system-ui,sans-serif;margin:2em;color:#222}table{border-collapse:collapse;margin:1em 0}")
            .Append("th,td{border:1px solid #ccc;padding:.25em .6em;text-align:right}th{background:#f3f3f3}td.l,th.l{text-align:left}")
            .Append(".err{color:#a00}.note{color:#555}</style>\n</head>\n<body>\n");
        h.Append("<h1>").Append(E(title)).Append("</h1>\n<p>")
            .Append(Inv($"{s.Records.Count} matches, {s.Header.Entrants.Count} entrants, {s.Header.Seeds} seeds from {s.Header.FirstSeed}, {s.Header.Cycles} cycles each. "))
            .Append(E(StandingsText.Method(s))).Append("</p>\n");
        Table(h, s);
        if (StandingsText.Ties(s) is { } ties)
        {
            h.Append("<p class=\"note\">").Append(E(ties)).Append("</p>\n");
        }

        Points(h, s);
        Cup(h, s, hasReplay);
        Entrants(h, s, teamNames);
        Faults(h, s, hasReplay);
        h.Append("<h2>Intervals</h2>\n");
        Plot(h, s);
        if (s.Teams >= 2)
        {
            h.Append("<h2>Wins, draws and losses</h2>\n<p class=\"note\">Row against column, both sides of the field together.</p>\n");
            Matrix(h, s);
        }

        h.Append("<h2>Matches</h2>\n");
        Matches(h, s, hasReplay);
        h.Append("</body>\n</html>\n");
        return h.ToString();
    }

    private static void Table(StringBuilder h, Standings s)
    {
        bool one = s.Teams == 1;
        h.Append("<table>\n<tr><th>Rank</th><th class=\"l\">Entrant</th><th>").Append(one ? "Mean score" : "Rating").Append("</th><th>95 % interval</th><th>Played</th>")
            .Append(one ? "<th>Mean length (s)</th>" : "<th>Wins</th><th>Draws</th><th>Losses</th>").Append("<th>Overlaps ranks</th></tr>\n");
        foreach (var r in s.Rows)
        {
            h.Append(Inv($"<tr><td>{r.Rank}</td><td class=\"l\">")).Append(E(r.Name));
            if (r.Error is not null)
            {
                h.Append("<br><span class=\"err\">not loaded: ").Append(E(StandingsText.Line(r.Error))).Append("</span>");
            }

            h.Append("</td><td>").Append(StandingsText.Value(s, r.Rating)).Append("</td><td>").Append(StandingsText.Interval(s, r.Interval))
                .Append(Inv($"</td><td>{r.Played}</td>"));
            h.Append(one ? Inv($"<td>{StandingsJson.Round(r.Seconds, 1):0.0}</td>") : Inv($"<td>{r.Wins}</td><td>{r.Draws}</td><td>{r.Losses}</td>"));
            h.Append("<td>").Append(StandingsText.Overlaps(r)).Append("</td></tr>\n");
        }

        h.Append("</table>\n");
    }

    // Each entrant's code: its folder or file, the version (a hash of its files) and the team's own name.
    private static void Entrants(StringBuilder h, Standings s, IReadOnlyList<string?>? teamNames)
    {
        if (!StandingsText.ShowsEntrants(s))
        {
            return;
        }

        h.Append("<h2>Entrants</h2>\n<p class=\"note\">The version is a hash of the entrant's files: a new version plays its matches again.</p>\n");
        h.Append("<table>\n<tr><th class=\"l\">Entrant</th><th class=\"l\">Code</th><th class=\"l\">Version</th><th class=\"l\">Team name</th></tr>\n");
        foreach (var r in s.Rows)
        {
            var e = s.Header.Entrants[r.Entrant];
            string? own = teamNames is not null && r.Entrant < teamNames.Count ? teamNames[r.Entrant] : null;
            h.Append("<tr><td class=\"l\">").Append(E(r.Name)).Append("</td><td class=\"l\">").Append(E(e.Spec)).Append("</td><td class=\"l\"><code>")
                .Append(E(e.Version ?? "-")).Append("</code></td><td class=\"l\">").Append(E(own ?? "-")).Append("</td></tr>\n");
        }

        h.Append("</table>\n");
    }

    // The entrants whose strategies had runtime faults, with a link to the first fault's cycle in its replay page.
    private static void Faults(StringBuilder h, Standings s, Func<int, bool> hasReplay)
    {
        if (!s.AnyFaults)
        {
            return;
        }

        h.Append("<h2>Runtime faults</h2>\n<p class=\"note\">Calls that threw, missed their deadline or answered badly, and strategy hosts that ended before their match; the first fault links to its cycle in the match's replay page when there is one (<code>--replays</code>).</p>\n");
        h.Append("<table>\n<tr><th class=\"l\">Entrant</th><th>Exceptions</th><th>Timeouts</th><th>Bad answers</th><th>Host ends</th><th>Matches</th><th class=\"l\">First fault</th></tr>\n");
        foreach (var r in s.Rows)
        {
            if (r.Faults is not { } f)
            {
                continue;
            }

            h.Append("<tr><td class=\"l\">").Append(E(r.Name)).Append(Inv($"</td><td>{f.Exceptions}</td><td>{f.Timeouts}</td><td>{f.BadAnswers}</td><td>{f.HostEnds}</td><td>{f.Matches}</td><td class=\"l err\">"));
            h.Append(hasReplay(f.FirstMatch) ? "<a href=\"" + E(f.ReplayLink()) + "\">" + E(f.Where()) + "</a>" : E(f.Where()));
            h.Append(": ").Append(E(Engine.Messages.MessageText.Escape(StandingsText.Line(f.FirstText)))).Append("</td></tr>\n");
        }

        h.Append("</table>\n");
    }

    // One row per entrant by rank: its interval as a bar, its rating as a dot, on a common axis.
    private static void Plot(StringBuilder h, Standings s)
    {
        const int left = 160, width = 480, row = 24, top = 10;
        double lo = s.Rows.Min(r => Math.Min(r.Interval.Low, r.Rating));
        double hi = s.Rows.Max(r => Math.Max(r.Interval.High, r.Rating));
        if (hi - lo < 1e-9)
        {
            lo -= 1;
            hi += 1;
        }

        double pad = (hi - lo) * 0.05;
        lo -= pad;
        hi += pad;
        double X(double v) => left + ((v - lo) / (hi - lo) * width);
        int height = top + (row * s.Rows.Count) + 30;
        h.Append(Inv($"<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{left + width + 20}\" height=\"{height}\" role=\"img\" aria-label=\"95 % intervals\" font-size=\"12\">\n"));
        for (int k = 0; k < s.Rows.Count; k++)
        {
            var r = s.Rows[k];
            double y = top + (row * k) + (row / 2.0);
            h.Append(Inv($"<text x=\"{left - 8}\" y=\"{y + 4:0.#}\" text-anchor=\"end\">{r.Rank}. ")).Append(E(r.Name)).Append("</text>\n");
            h.Append(Inv($"<line x1=\"{X(r.Interval.Low):0.#}\" y1=\"{y:0.#}\" x2=\"{X(r.Interval.High):0.#}\" y2=\"{y:0.#}\" stroke=\"#369\" stroke-width=\"3\"/>"));
            h.Append(Inv($"<circle cx=\"{X(r.Rating):0.#}\" cy=\"{y:0.#}\" r=\"4\" fill=\"#c33\"><title>")).Append(E(r.Name)).Append(": ")
                .Append(StandingsText.Value(s, r.Rating)).Append(" (").Append(StandingsText.Interval(s, r.Interval)).Append(")</title></circle>\n");
        }

        double axis = top + (row * s.Rows.Count) + 4;
        h.Append(Inv($"<line x1=\"{left}\" y1=\"{axis:0.#}\" x2=\"{left + width}\" y2=\"{axis:0.#}\" stroke=\"#888\"/>\n"));
        for (int t = 0; t <= 4; t++)
        {
            double v = lo + ((hi - lo) * t / 4);
            h.Append(Inv($"<text x=\"{X(v):0.#}\" y=\"{axis + 16:0.#}\" text-anchor=\"middle\">{StandingsText.Value(s, v)}</text>\n"));
        }

        h.Append("</svg>\n");
    }

    private static void Matrix(StringBuilder h, Standings s)
    {
        h.Append("<table>\n<tr><th></th>");
        foreach (var c in s.Rows)
        {
            h.Append("<th>").Append(E(c.Name)).Append("</th>");
        }

        h.Append("</tr>\n");
        foreach (var r in s.Rows)
        {
            h.Append("<tr><th class=\"l\">").Append(E(r.Name)).Append("</th>");
            foreach (var c in s.Rows)
            {
                var x = s.Wdl[r.Entrant, c.Entrant];
                h.Append(r.Entrant == c.Entrant ? "<td>-</td>" : Inv($"<td>{x.W}-{x.D}-{x.L}</td>"));
            }

            h.Append("</tr>\n");
        }

        h.Append("</table>\n");
    }

    private static void Matches(StringBuilder h, Standings s, Func<int, bool> hasReplay)
    {
        var teams = Enumerable.Range(0, s.Teams).Select(t => Inv($"<th class=\"l\">Team {t}</th>"));
        h.Append("<table>\n<tr><th>Match</th><th>Seed</th>").Append(string.Concat(teams)).Append("<th>Score</th><th class=\"l\">Result</th><th>Replay</th></tr>\n");
        foreach (var m in s.Records)
        {
            h.Append(Inv($"<tr><td>{m.Index}</td><td>{m.Seed}</td>"));
            foreach (string name in m.Entrants)
            {
                h.Append("<td class=\"l\">").Append(E(name)).Append("</td>");
            }

            if (m.Result is { } r)
            {
                string score = string.Join(" : ", (r.Scores ?? [r.Goals0, r.Goals1]).Select(x => x.ToString(CultureInfo.InvariantCulture)));
                string result = r.Winner >= 0 && r.Winner < m.Entrants.Count ? m.Entrants[r.Winner] + " wins: " + r.Rule : r.Rule ?? "no winner";
                h.Append("<td>").Append(score).Append("</td><td class=\"l\">").Append(E(result)).Append("</td><td>");
                h.Append(hasReplay(m.Index) ? Inv($"<a href=\"replays/match-{m.Index}.html\">replay</a>") : "-");
            }
            else
            {
                var who = m.Forfeits.Select(t => m.Entrants[t]);
                h.Append("<td>-</td><td class=\"l err\">forfeit: ").Append(E(string.Join(", ", who))).Append(" not loaded</td><td>-");
            }

            h.Append("</td></tr>\n");
        }

        h.Append("</table>\n");
    }

    // A group stage and knockout: each group's table, then the bracket, a column per round, each pairing's matches linked to their replay pages.
    private static void Cup(StringBuilder h, Standings s, Func<int, bool> hasReplay)
    {
        if (s.Cup is not { } cup)
        {
            return;
        }

        h.Append("<style>.bracket{display:flex;gap:1.5em;align-items:stretch;margin:1em 0}.round{display:flex;flex-direction:column;justify-content:space-around;gap:1em;min-width:14em}")
            .Append(".round h3{margin:0;font-size:1em}.tie{border:1px solid #ccc;border-radius:4px;padding:.3em .5em}.side{display:flex;justify-content:space-between;gap:1em}")
            .Append(".side.win{font-weight:bold}.from{color:#777;font-weight:normal}.games{color:#555;font-size:.85em}.champion{font-size:1.2em}</style>\n");
        h.Append("<h2>Groups</h2>\n<p class=\"note\">").Append(E(StandingsText.PointsRule)).Append(".</p>\n");
        foreach (var group in cup.Groups)
        {
            h.Append("<h3>Group ").Append(E(group.Name)).Append("</h3>\n");
            PointsRows(h, group.Table);
        }

        h.Append("<h2>Knockout</h2>\n<p class=\"note\">").Append(E(StandingsText.KnockoutRule)).Append(".</p>\n<div class=\"bracket\">\n");
        foreach (var round in cup.Rounds)
        {
            h.Append("<div class=\"round\"><h3>").Append(E(round.Name)).Append("</h3>\n");
            foreach (var tie in round.Ties)
            {
                h.Append("<div class=\"tie\">");
                Side(h, s, tie, tie.A, tie.WinsA);
                Side(h, s, tie, tie.B, tie.WinsB);
                if (tie.A is not null && tie.B is not null)
                {
                    h.Append("<div class=\"games\">");
                    var links = tie.Matches.Select(m => hasReplay(m.Index) ? Inv($"<a href=\"replays/match-{m.Index}.html\">{m.Index}</a>") : Inv($"{m.Index}"));
                    h.Append(E(StandingsText.TieMatches(cup, tie))).Append("<br>goals ").Append(StandingsText.Pair(tie.GoalsA, tie.GoalsB))
                        .Append("; matches ").Append(string.Join(", ", links)).Append("</div>");
                }

                h.Append("<div class=\"games\">").Append(E(tie.DecidedBy is null ? "not decided yet" : "decided by " + tie.DecidedBy)).Append("</div></div>\n");
            }

            h.Append("</div>\n");
        }

        string champion = cup.Champion is null ? "not decided yet" : s.Header.Entrants[cup.Champion.Entrant].Name;
        h.Append("<div class=\"round\"><h3>champion</h3><div class=\"tie champion\"><strong>").Append(E(champion)).Append("</strong></div></div>\n</div>\n");
    }

    // One side of a knockout pairing: its name, where it came from, its wins; the side that goes on in bold.
    private static void Side(StringBuilder h, Standings s, CupTie tie, CupSlot? slot, int wins)
    {
        if (slot is null)
        {
            h.Append("<div class=\"side\"><span class=\"from\">bye</span></div>");
            return;
        }

        bool on = tie.Winner?.Entrant == slot.Entrant;
        bool bye = tie.A is null || tie.B is null;
        h.Append(on ? "<div class=\"side win\">" : "<div class=\"side\">").Append("<span>").Append(E(s.Header.Entrants[slot.Entrant].Name))
            .Append(" <span class=\"from\">").Append(E(slot.From)).Append("</span></span><span>").Append(bye ? string.Empty : Inv($"{wins}")).Append("</span></div>");
    }

    // The rows of a points table.
    private static void PointsRows(StringBuilder h, IReadOnlyList<PointsRow> rows)
    {
        h.Append("<table>\n<tr><th>Rank</th><th class=\"l\">Entrant</th><th>Played</th><th>Won</th><th>Drawn</th><th>Lost</th><th>Goals for</th><th>Goals against</th><th>Goal difference</th><th>Points</th></tr>\n");
        foreach (var p in rows)
        {
            h.Append(Inv($"<tr><td>{p.Rank}</td><td class=\"l\">")).Append(E(p.Name))
                .Append(Inv($"</td><td>{p.Played}</td><td>{p.Won}</td><td>{p.Drawn}</td><td>{p.Lost}</td><td>{p.GoalsFor}</td><td>{p.GoalsAgainst}</td><td>{StandingsText.Signed(p.GoalDifference)}</td><td>{p.Points}</td></tr>\n"));
        }

        h.Append("</table>\n");
    }

    // The points table (items of two or more teams).
    private static void Points(StringBuilder h, Standings s)
    {
        if (s.Points.Count == 0)
        {
            return;
        }

        h.Append("<h2>Points table</h2>\n<p class=\"note\">").Append(E(StandingsText.PointsRule)).Append(".</p>\n");
        h.Append("<table>\n<tr><th>Rank</th><th class=\"l\">Entrant</th><th>Played</th><th>Won</th><th>Drawn</th><th>Lost</th><th>Goals for</th><th>Goals against</th><th>Goal difference</th><th>Points</th></tr>\n");
        foreach (var p in s.Points)
        {
            h.Append(Inv($"<tr><td>{p.Rank}</td><td class=\"l\">")).Append(E(p.Name))
                .Append(Inv($"</td><td>{p.Played}</td><td>{p.Won}</td><td>{p.Drawn}</td><td>{p.Lost}</td><td>{p.GoalsFor}</td><td>{p.GoalsAgainst}</td><td>{StandingsText.Signed(p.GoalDifference)}</td><td>{p.Points}</td></tr>\n"));
        }

        h.Append("</table>\n");
    }

    private static string E(string text) => WebUtility.HtmlEncode(text);

    private static string Inv(FormattableString text) => text.ToString(CultureInfo.InvariantCulture);
}
