namespace URWPGSim2D.Tournament.Batch;

/// <summary>
/// The text a batch prints: one line per match and the aggregate (goals per team: mean, sample
/// standard deviation, range, total; outcomes; largest leftover overlap; strategy faults). The
/// same results give the same text, whether they come from one run or a merge of shards.
/// </summary>
public static class BatchSummary
{
    private static readonly CultureInfo C = CultureInfo.InvariantCulture;

    /// <summary>The line of one match.</summary>
    public static string Line(MatchResult r) => r.Failed is { } why
        ? string.Create(C, $"match {r.Index} (seed {r.Seed}): failed inside the server: {why}\n")
        : string.Create(C, $"match {r.Index} (seed {r.Seed}): {Result(r)}, contacts {r.TotalContacts}, contact events {r.Events}, sub-steps {r.SubSteps}, overlap {r.LeftoverOverlap:0.000} mm, faults {r.StrategyFaults}\n");

    // The score and who won by which rule: "score 1-1, team 0 won by earlier first score";
    // "score 0-0, none: tie"; without an item, the goals.
    private static string Result(MatchResult r)
    {
        if (r.Scores is not { } scores)
        {
            return string.Create(C, $"goals {r.Goals0}-{r.Goals1}");
        }

        string score = string.Join("-", System.Array.ConvertAll(scores, v => v < 0 ? "n/a" : v.ToString(C)));
        string rule = r.Rule ?? "no rule";
        return r.Winner >= 0
            ? string.Create(C, $"score {score}, team {r.Winner} won by {rule}")
            : string.Create(C, $"score {score}, no winner: {rule}");
    }

    /// <summary>The aggregate of <paramref name="results"/> (in match order), several lines ending in a newline.</summary>
    public static string Aggregate(BatchHeader header, IReadOnlyList<MatchResult> results)
    {
        var s = new StringBuilder();
        string share = header.ShardCount > 1
            ? string.Create(C, $"{results.Count} of {header.Matches} matches (shard {header.ShardIndex}/{header.ShardCount})")
            : string.Create(C, $"{results.Count} matches");
        s.Append(C, $"batch: {share}, seeds {header.FirstSeed} to {header.FirstSeed + (ulong)header.Matches - 1}, {header.Cycles} cycles each, scene {header.Scene}\n");
        string[] teams = header.Teams.Split(';');
        int teamCount = Math.Max(2, teams.Length);
        foreach (var r in results)
        {
            teamCount = Math.Max(teamCount, r.Scores?.Length ?? 0);
        }

        for (int team = 0; team < teamCount; team++)
        {
            var goals = new double[results.Count];
            for (int i = 0; i < results.Count; i++)
            {
                goals[i] = Goals(results[i], team);
            }

            var (mean, sd, min, max, total) = Stats(goals);
            string label = team < teams.Length ? teams[team] : "?";
            s.Append(C, $"goals team {team} ({label}): mean {mean:0.000}, sd {sd:0.000}, min {min}, max {max}, total {total}\n");
        }

        var won = new int[teamCount];
        int drawn = 0, faults = 0, worst = -1;
        for (int i = 0; i < results.Count; i++)
        {
            var r = results[i];
            // An item's winner follows its own rules (tie deciders); plain matches by goals.
            int winner = r.Item is not null ? r.Winner : r.Goals0 > r.Goals1 ? 0 : r.Goals1 > r.Goals0 ? 1 : -1;
            if ((uint)winner < (uint)teamCount)
            {
                won[winner]++;
            }

            drawn += winner < 0 ? 1 : 0;
            faults += r.StrategyFaults;
            worst = worst < 0 || r.LeftoverOverlap > results[worst].LeftoverOverlap ? i : worst;
        }

        s.Append("outcomes:");
        for (int team = 0; team < teamCount; team++)
        {
            s.Append(C, $" team {team} won {won[team]},");
        }

        s.Append(C, $" drawn {drawn}\n");
        s.Append(worst < 0
            ? "largest leftover overlap: none\n"
            : string.Create(C, $"largest leftover overlap: {results[worst].LeftoverOverlap:0.000} mm (match {results[worst].Index}, cycle {results[worst].LeftoverCycle})\n"));
        s.Append(C, $"strategy faults: {faults}\n");
        return s.ToString();
    }

    // A team's goals (an item's score) in one match: teams 0 and 1 from the goals, further teams from the scores.
    private static int Goals(MatchResult r, int team) => team switch
    {
        0 => r.Goals0,
        1 => r.Goals1,
        _ => r.Scores is { } scores && team < scores.Length ? scores[team] : 0,
    };

    /// <summary>Mean, sample standard deviation (0 for fewer than two values), min, max and total.</summary>
    public static (double Mean, double Sd, double Min, double Max, double Total) Stats(IReadOnlyList<double> values)
    {
        if (values.Count == 0)
        {
            return (0, 0, 0, 0, 0);
        }

        double total = 0, min = double.PositiveInfinity, max = double.NegativeInfinity;
        foreach (double v in values)
        {
            total += v;
            min = Math.Min(min, v);
            max = Math.Max(max, v);
        }

        double mean = total / values.Count;
        double squares = 0;
        foreach (double v in values)
        {
            squares += (v - mean) * (v - mean);
        }

        double sd = values.Count > 1 ? Math.Sqrt(squares / (values.Count - 1)) : 0;
        return (mean, sd, min, max, total);
    }
}
