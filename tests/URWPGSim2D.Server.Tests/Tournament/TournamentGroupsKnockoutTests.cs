namespace URWPGSim2D.Server.Tests.Tournament;

/// <summary>
/// The group stage and knockout (<see cref="GroupsKnockout"/>): snake-seeded groups, brackets of 4, 5, 6
/// and 8 entrants worked out by hand (byes, cross-over pairing, the same group kept apart in the first
/// round), how a knockout pairing is decided (wins with the item's own tie rules, goal difference, further
/// seeds, seeding, a forfeit), and random group results against the bracket's invariants.
/// </summary>
public sealed class TournamentGroupsKnockoutTests
{
    [Fact]
    public void Snake_seeding_deals_the_entrants_A_B_B_A_and_each_group_plays_a_round_robin()
    {
        var cup = new GroupsKnockout(8, 2, 2, 2, 3, 1);
        Assert.Equal(new[] { new[] { 0, 3, 4, 7 }, [1, 2, 5, 6] }, cup.Groups.Select(g => g.ToArray()).ToArray());
        var three = new GroupsKnockout(7, 3, 1, 1, 1, 1);
        Assert.Equal(new[] { new[] { 0, 5, 6 }, [1, 4], [2, 3] }, three.Groups.Select(g => g.ToArray()).ToArray());
        var given = new GroupsKnockout(4, 2, 1, 1, 1, 1, [3, 2, 1, 0]);
        Assert.Equal(new[] { new[] { 3, 0 }, [2, 1] }, given.Groups.Select(g => g.ToArray()).ToArray());

        // 2 seeds × 2 groups × 12 ordered pairs; seed by seed, group by group; never two groups in a match.
        Assert.Equal(48, cup.GroupMatches.Count);
        Assert.Equal(Enumerable.Range(0, 48), cup.GroupMatches.Select(m => m.Index));
        Assert.All(cup.GroupMatches.Take(24), m => Assert.Equal(1UL, m.Seed));
        Assert.All(cup.GroupMatches, m => Assert.Equal(cup.GroupOf[m.Sides[0]], cup.GroupOf[m.Sides[1]]));
        Assert.Equal(new[] { 0, 3 }, cup.GroupMatches[0].Sides);
        Assert.Equal(48 + (2 * 2 * 2) + (2 * 3), cup.PlannedMatches);
    }

    [Fact]
    public void Bracket_positions_put_seed_1_against_the_last_and_the_best_two_in_opposite_halves()
    {
        Assert.Equal([1, 2], GroupsKnockout.BracketOrder(2));
        Assert.Equal([1, 4, 2, 3], GroupsKnockout.BracketOrder(4));
        Assert.Equal([1, 8, 4, 5, 2, 7, 3, 6], GroupsKnockout.BracketOrder(8));
        Assert.Equal(["final", "semi-finals", "quarter-finals", "round of 16"], new[] { 1, 2, 4, 8 }.Select(GroupsKnockout.RoundName));
    }

    [Fact]
    public void Four_entrants_in_two_groups_cross_over_into_semi_finals_and_a_final()
    {
        // Strength by index: entrant 0 beats every other, 3 loses to all. Groups: A = 0, 3; B = 1, 2.
        var cup = new GroupsKnockout(4, 2, 2, 1, 1, 1);
        var b = Play(cup, Strength(4, 3, 2, 1, 0));
        Assert.Equal(["A1 0 v B2 2", "B1 1 v A2 3"], Ties(b, 0));
        Assert.Equal(["A1 0 v B1 1"], Ties(b, 1));
        Assert.Equal(0, b.Champion!.Entrant);
        Assert.Equal(["semi-finals", "final"], b.Rounds.Select(r => r.Name));

        // Group stage 4 matches (seed 1), each semi-final both sides on seed 2, the final on seed 2: 10, as planned.
        Assert.Equal(10, b.Matches.Count);
        Assert.Equal(cup.PlannedMatches, b.Matches.Count);
        var first = b.Rounds[0].Ties[0];
        Assert.Equal([(2UL, 0, 2), (2UL, 2, 0)], first.Matches.Select(m => (m.Seed, m.Sides[0], m.Sides[1])));
        Assert.Equal(((4, 5), (7, 8)), ((first.Matches[0].Index, first.Matches[1].Index), (b.Rounds[0].Ties[1].Matches[1].Index, b.Rounds[1].Ties[0].Matches[0].Index)));
        Assert.Equal((2, 0, "wins"), (first.WinsA, first.WinsB, first.DecidedBy));
        Assert.Equal(["champion", "final", "semi-finals", "semi-finals"], Enumerable.Range(0, 4).Select(b.Reached));
        Assert.Equal(("knockout", "final"), b.Stages[9]);
        Assert.Equal(("group", "B"), b.Stages[2]);
    }

    [Fact]
    public void Five_entrants_in_one_group_with_three_going_on_give_the_winner_a_bye()
    {
        var cup = new GroupsKnockout(5, 1, 3, 1, 2, 1);
        var b = Play(cup, Strength(5, 4, 3, 2, 1, 0));
        Assert.Equal(["A1 0 bye", "A2 1 v A3 2"], Ties(b, 0));
        Assert.Equal("bye", b.Rounds[0].Ties[0].DecidedBy);
        Assert.Equal(0, b.Rounds[0].Ties[0].Winner!.Entrant);
        Assert.Empty(b.Rounds[0].Ties[0].Matches);
        Assert.Equal(["A1 0 v A2 1"], Ties(b, 1));
        Assert.Equal(4, b.Rounds[1].Ties[0].Matches.Count); // the final on 2 seeds, both sides
        Assert.Equal(0, b.Champion!.Entrant);
        Assert.Equal(["champion", "final", "semi-finals", "group", "group"], Enumerable.Range(0, 5).Select(b.Reached));
    }

    [Fact]
    public void Six_entrants_in_three_groups_give_the_two_best_winners_byes_and_keep_a_group_apart()
    {
        // A = 0, 5; B = 1, 4; C = 2, 3. Seeds A1 B1 C1 A2 B2 C2; C1 would meet C2: C2 swaps with B2.
        var cup = new GroupsKnockout(6, 3, 2, 1, 1, 1);
        var b = Play(cup, Strength(6, 5, 4, 3, 2, 1, 0));
        Assert.Equal(["A1 0 bye", "A2 5 v C2 3", "B1 1 bye", "C1 2 v B2 4"], Ties(b, 0));
        Assert.Equal("quarter-finals", b.Rounds[0].Name);
        Assert.Equal(["A1 0 v C2 3", "B1 1 v C1 2"], Ties(b, 1));
        Assert.Equal(0, b.Champion!.Entrant);

        // Three winners only: the best gets a bye.
        var winners = Play(new GroupsKnockout(6, 3, 1, 1, 1, 1), Strength(6, 5, 4, 3, 2, 1, 0));
        Assert.Equal(["A1 0 bye", "B1 1 v C1 2"], Ties(winners, 0));
    }

    [Fact]
    public void Eight_entrants_in_two_or_four_groups_cross_over()
    {
        var two = Play(new GroupsKnockout(8, 2, 2, 1, 1, 1), Strength(8, 7, 6, 5, 4, 3, 2, 1, 0));
        Assert.Equal(["A1 0 v B2 2", "B1 1 v A2 3"], Ties(two, 0));

        var four = Play(new GroupsKnockout(8, 4, 2, 1, 1, 1), Strength(8, 7, 6, 5, 4, 3, 2, 1, 0));
        Assert.Equal(["A1 0 v D2 4", "D1 3 v A2 7", "B1 1 v C2 5", "C1 2 v B2 6"], Ties(four, 0));
        Assert.Equal(["A1 0 v D1 3", "B1 1 v C1 2"], Ties(four, 1));
        Assert.Equal(["A1 0 v B1 1"], Ties(four, 2));
        Assert.Equal(0, four.Champion!.Entrant);
    }

    [Fact]
    public void A_pairing_goes_by_wins_then_goal_difference_then_further_seeds_then_the_seeding()
    {
        var cup = new GroupsKnockout(2, 1, 2, 1, 1, 1); // a final only, on seed 2

        // One win and a draw beat a draw and a loss.
        var wins = Play(cup, Scripted((m, a) => m.Seed == 2 ? (a ? (1, 0) : (0, 0)) : (0, 0)));
        Assert.Equal(("wins", 0), (wins.Rounds[0].Ties[0].DecidedBy, wins.Champion!.Entrant));

        // One win each: entrant 0 won 1:0, entrant 1 3:1; goals 2:3, so entrant 1 goes on.
        var difference = Play(cup, Scripted((m, a) => m.Seed == 2 ? (a ? (1, 0) : (1, 3)) : (0, 0)));
        var tie = difference.Rounds[0].Ties[0];
        Assert.Equal(("goal difference", 1, 1, 1, 2, 3), (tie.DecidedBy, tie.Winner!.Entrant, tie.WinsA, tie.WinsB, tie.GoalsA, tie.GoalsB));

        // Level on seed 2: a further seed, 3, where entrant 1 wins.
        var further = Play(cup, Scripted((m, a) => m.Seed == 3 ? (a ? (0, 2) : (0, 0)) : (0, 0)));
        tie = further.Rounds[0].Ties[0];
        Assert.Equal(("wins", 1, 4), (tie.DecidedBy, tie.Winner!.Entrant, tie.Matches.Count));
        Assert.Equal(["group stage", "final", "final, further seed 1"], further.Steps.Select(s => s.Label));

        // Level every time: three further seeds, then the better seed (group A's winner; both drew: the name decides, "e0").
        var level = Play(cup, Scripted((_, _) => (1, 1)));
        tie = level.Rounds[0].Ties[0];
        Assert.Equal(("seeding", 0, 2 * (1 + GroupsKnockout.MaximumFurtherSeeds)), (tie.DecidedBy, tie.Winner!.Entrant, tie.Matches.Count));
        Assert.Equal([2UL, 2, 3, 3, 4, 4, 5, 5], tie.Matches.Select(m => m.Seed));
    }

    [Fact]
    public void The_items_own_tie_rules_decide_a_match_with_equal_goals_and_a_forfeit_is_a_win()
    {
        var cup = new GroupsKnockout(2, 1, 2, 1, 1, 1);
        var names = Names(2);

        // As water polo's penalties decide a match level after extra time: 2:2, and the item names entrant 1's team the winner, twice.
        var penalties = Unfold(cup, m => m.Seed == 1 ? Record(m, names, 0, 0, -1) : Record(m, names, 2, 2, m.Sides[0] == 1 ? 0 : 1));
        var tie = penalties.Rounds[0].Ties[0];
        Assert.Equal(("wins", 1, 2, 0), (tie.DecidedBy, tie.Winner!.Entrant, tie.WinsB, tie.WinsA));

        // Entrant 1 cannot be loaded: it forfeits both knockout matches.
        var forfeit = Unfold(cup, m => m.Seed == 1 ? Record(m, names, 0, 0, -1) : new TournamentRecord(m.Index, m.Seed, [names[m.Sides[0]], names[m.Sides[1]]], null, [m.Sides[0] == 1 ? 0 : 1], ["no strategy class"]));
        tie = forfeit.Rounds[0].Ties[0];
        Assert.Equal(("wins", 0, 2, 0), (tie.DecidedBy, tie.Winner!.Entrant, tie.WinsA, tie.GoalsA + tie.GoalsB + tie.WinsB));
    }

    [Fact]
    public void Unfolding_stops_at_the_first_step_not_played_and_the_indices_depend_only_on_the_results()
    {
        var cup = new GroupsKnockout(4, 2, 2, 1, 1, 1);
        var names = Names(4);
        var played = new Dictionary<int, TournamentRecord>();
        var none = cup.Unfold(names, m => played.GetValueOrDefault(m.Index));
        Assert.Equal(["group stage"], none.Steps.Select(s => s.Label));
        Assert.Empty(none.Groups);
        Assert.False(none.Complete);
        foreach (var m in cup.GroupMatches)
        {
            played[m.Index] = Record(m, names, m.Sides[0] < m.Sides[1] ? 1 : 0, 0, -2);
        }

        var semis = cup.Unfold(names, m => played.GetValueOrDefault(m.Index));
        Assert.Equal(["group stage", "semi-finals"], semis.Steps.Select(s => s.Label));
        Assert.Null(semis.Rounds[0].Ties[0].Winner);
        Assert.Equal(8, semis.Matches.Count);
        var whole = Play(cup, Strength(4, 3, 2, 1, 0));
        Assert.Equal(semis.Matches.Select(m => (m.Index, m.Seed, m.Sides[0], m.Sides[1])), whole.Matches.Take(8).Select(m => (m.Index, m.Seed, m.Sides[0], m.Sides[1])));
    }

    [Fact]
    public void Counts_the_entrants_cannot_fill_are_refused_naming_the_option()
    {
        Assert.StartsWith("--groups 3: 3 groups need at least 6 entrants (two a group), got 5", Assert.Throws<ArgumentException>(() => new GroupsKnockout(5, 3, 1, 1, 1, 1)).Message, StringComparison.Ordinal);
        Assert.StartsWith("--advance 3: must be 1 … 2", Assert.Throws<ArgumentException>(() => new GroupsKnockout(5, 2, 3, 1, 1, 1)).Message, StringComparison.Ordinal);
        Assert.StartsWith("--advance 1: one group", Assert.Throws<ArgumentException>(() => new GroupsKnockout(5, 1, 1, 1, 1, 1)).Message, StringComparison.Ordinal);
        Assert.StartsWith("--seed ", Assert.Throws<ArgumentException>(() => new GroupsKnockout(4, 2, 1, 1, 1, long.MaxValue - 3)).Message, StringComparison.Ordinal);
    }

    [Fact]
    public void Random_group_results_keep_the_brackets_invariants()
    {
        var random = new Random(4141);
        for (int round = 0; round < 150; round++)
        {
            int groups = random.Next(1, 5);
            int entrants = (2 * groups) + random.Next(0, 7);
            int advance = random.Next(1, (entrants / groups) + 1);
            if (groups * advance < 2)
            {
                advance = 2;
            }

            int seeds = random.Next(1, 3), finals = random.Next(1, 4);
            var cup = new GroupsKnockout(entrants, groups, advance, seeds, finals, (ulong)random.Next(0, 50));
            var names = Names(entrants);
            var results = new Dictionary<int, (int, int, int)>();
            var b = Play(cup, m => results.TryGetValue(m.Index, out var r) ? r : results[m.Index] = Random(random));
            string where = $"{entrants} entrants, {groups} groups, top {advance}";

            // Every entrant plays every other of its group on both sides on each seed, and no one else there.
            foreach (var group in cup.Groups)
            {
                foreach (int e in group)
                {
                    Assert.Equal(2 * seeds * (group.Count - 1), cup.GroupMatches.Count(m => m.Sides.Contains(e)));
                }
            }

            Assert.All(cup.GroupMatches, m => Assert.Equal(cup.GroupOf[m.Sides[0]], cup.GroupOf[m.Sides[1]]));

            // The qualifiers are the top K of each group's table, once each.
            var qualifiers = b.Rounds[0].Ties.SelectMany(t => new[] { t.A, t.B }).OfType<CupSlot>().ToList();
            Assert.Equal(groups * advance, qualifiers.Select(q => q.Entrant).Distinct().Count());
            Assert.Equal(b.Groups.SelectMany(g => g.Table.Take(advance).Select(p => p.Entrant)).OrderBy(x => x), qualifiers.Select(q => q.Entrant).OrderBy(x => x));

            // Rounds halve; each round's sides are the winners of the round before; a loser plays no later round.
            Assert.Equal(cup.BracketSize / 2, b.Rounds[0].Ties.Count);
            for (int r = 1; r < b.Rounds.Count; r++)
            {
                Assert.Equal(b.Rounds[r - 1].Ties.Count / 2, b.Rounds[r].Ties.Count);
                var before = b.Rounds[r - 1].Ties.Select(t => t.Winner!.Entrant).ToList();
                Assert.Equal(before, b.Rounds[r].Ties.SelectMany(t => new[] { t.A!.Entrant, t.B!.Entrant }));
                var losers = b.Rounds[r - 1].Ties.SelectMany(t => new[] { t.A, t.B }).OfType<CupSlot>().Select(s => s.Entrant).Except(before);
                Assert.All(b.Rounds.Skip(r).SelectMany(x => x.Ties).SelectMany(t => t.Matches), m => Assert.Empty(m.Sides.Intersect(losers)));
            }

            // Exactly one champion: the final's winner, the only entrant that reached "champion".
            Assert.True(b.Complete, where);
            Assert.Equal("final", b.Rounds[^1].Name);
            Assert.Equal(b.Rounds[^1].Ties.Single().Winner, b.Champion);
            Assert.Single(Enumerable.Range(0, entrants), e => b.Reached(e) == "champion");

            // Each pairing's winner is one of its sides, decided as documented; the knockout's seeds follow the group stage's.
            foreach (var tie in b.Rounds.SelectMany(r => r.Ties))
            {
                Assert.Contains(tie.Winner, new[] { tie.A, tie.B });
                switch (tie.DecidedBy)
                {
                    case "wins": Assert.Equal(tie.Winner == tie.A, tie.WinsA > tie.WinsB); break;
                    case "goal difference": Assert.Equal((tie.WinsA, tie.Winner == tie.A), (tie.WinsB, tie.GoalsA > tie.GoalsB)); break;
                    case "seeding": Assert.Equal((tie.WinsA, tie.GoalsA, tie.Winner!.Seed), (tie.WinsB, tie.GoalsB, Math.Min(tie.A!.Seed, tie.B!.Seed))); break;
                    case "bye": Assert.True(tie.A is null || tie.B is null); break;
                    default: Assert.Fail($"{where}: decided by {tie.DecidedBy}"); break;
                }

                Assert.All(tie.Matches, m => Assert.True(m.Seed >= cup.FirstSeed + (ulong)seeds, where));
            }

            // With two or more groups and two going on from each, no two entrants of one group meet in the first round.
            if (groups >= 2 && advance <= 2)
            {
                Assert.All(b.Rounds[0].Ties.Where(t => t.A is not null && t.B is not null), t => Assert.NotEqual(cup.GroupOf[t.A!.Entrant], cup.GroupOf[t.B!.Entrant]));
            }

            Assert.Equal(Enumerable.Range(0, b.Matches.Count), b.Matches.Select(m => m.Index));
            Assert.True(b.Matches.Count >= cup.PlannedMatches, where);
        }
    }

    [Fact]
    public void Every_file_shows_the_groups_the_bracket_with_its_bye_and_the_champion()
    {
        var cup = new GroupsKnockout(5, 1, 3, 1, 1, 1);
        var b = Play(cup, Strength(5, 4, 3, 2, 1, 0));
        var names = Names(5);
        var records = b.Matches.Select(m => b.Records[m.Index]).ToList();
        var header = new TournamentHeader("ball-grab", [.. names.Select(n => new Entrant(n, "idle"))], 1, 1, 100, 100, records.Count);
        var s = Standings.Compute(header, 2, records, replicates: 20) with { Cup = b };

        string json = StandingsJson.Format(s);
        Assert.Contains("\n  \"groups\": [\n    {\"name\": \"A\", \"points\": [\n      {\"name\": \"e0\", \"rank\": 1, \"played\": 8, \"won\": 8,", json, StringComparison.Ordinal);
        Assert.Contains("{\"entrants\": [\"e0\", null], \"from\": [\"A1\", null], \"seeded\": [1, null], \"matches\": [], \"wins\": [0, 0], \"goals\": [0, 0], \"winner\": \"e0\", \"decidedBy\": \"bye\"}", json, StringComparison.Ordinal);
        Assert.Contains("{\"entrants\": [\"e1\", \"e2\"], \"from\": [\"A2\", \"A3\"], \"seeded\": [2, 3], \"matches\": [{\"match\": 20, \"seed\": 2, \"teams\": [\"e1\", \"e2\"], \"score\": [1, 0], \"winner\": \"e1\"}, {\"match\": 21, \"seed\": 2, \"teams\": [\"e2\", \"e1\"], \"score\": [0, 1], \"winner\": \"e1\"}], \"wins\": [2, 0], \"goals\": [2, 0], \"winner\": \"e1\", \"decidedBy\": \"wins\"}", json, StringComparison.Ordinal);
        Assert.EndsWith("    ],\n    \"champion\": \"e0\"\n  }\n}\n", json, StringComparison.Ordinal);
        using (var parsed = System.Text.Json.JsonDocument.Parse(json))
        {
            Assert.Equal(2, parsed.RootElement.GetProperty("knockout").GetProperty("rounds").GetArrayLength());
        }

        string md = StandingsMarkdown.Format(s);
        Assert.Contains("\nGroup A (3 points a win, 1 a draw; ties: goal difference, goals scored, head to head, name):\n", md, StringComparison.Ordinal);
        Assert.Contains("| semi-finals | e0 (A1), a bye | - | - | - | e0 | bye |\n| semi-finals | e1 (A2) v e2 (A3) | seed 2: 1:0, 1:0 | 2:0 | 2:0 | e1 | wins |\n| final | e0 (A1) v e1 (A2) | seed 2: 1:0, 1:0 | 2:0 | 2:0 | e0 | wins |\n", md, StringComparison.Ordinal);
        Assert.Contains("\nChampion: e0.\n", md, StringComparison.Ordinal);

        string html = ReportPage.Format(s, j => j == 20);
        Assert.Contains("<h3>Group A</h3>", html, StringComparison.Ordinal);
        Assert.Contains("<div class=\"side\"><span class=\"from\">bye</span></div>", html, StringComparison.Ordinal);
        Assert.Contains("matches <a href=\"replays/match-20.html\">20</a>, 21</div>", html, StringComparison.Ordinal);
        Assert.Contains("<h3>champion</h3><div class=\"tie champion\"><strong>e0</strong>", html, StringComparison.Ordinal);

        string[] standings = StandingsCsv.Standings(s).Split("\r\n");
        Assert.EndsWith(",group,group_rank,reached", standings[0], StringComparison.Ordinal);
        Assert.Equal(["champion", "final", "semi-finals", "group", "group"], Enumerable.Range(0, 5).Select(e => standings.Single(l => l.Split(',').Length > 2 && l.Split(',')[1] == names[e]).Split(',')[^1]));
        string[] matches = StandingsCsv.Matches(s).Split("\r\n");
        Assert.EndsWith(",forfeited,stage,round", matches[0], StringComparison.Ordinal);
        Assert.EndsWith(",group,A", matches[1], StringComparison.Ordinal);
        Assert.EndsWith(",knockout,final", matches[^2], StringComparison.Ordinal);

        // A round robin's files keep their columns and fields.
        var plain = s with { Cup = null };
        Assert.DoesNotContain("\"knockout\"", StandingsJson.Format(plain), StringComparison.Ordinal);
        Assert.EndsWith(",host_ends,error", StandingsCsv.Standings(plain).Split("\r\n")[0], StringComparison.Ordinal);
        Assert.EndsWith(",result,forfeited", StandingsCsv.Matches(plain).Split("\r\n")[0], StringComparison.Ordinal);
        Assert.DoesNotContain("bracket", ReportPage.Format(plain, _ => false), StringComparison.Ordinal);
    }

    private static (int, int, int) Random(Random random)
    {
        int a = random.Next(3), b = random.Next(3);
        return (a, b, a == b && random.Next(3) == 0 ? random.Next(2) : -2); // sometimes the item's tie rules decide a level match
    }

    // Plays the whole tournament: each match's score (and the item's winner, −2: the higher score) from the function.
    private static Bracket Play(GroupsKnockout cup, Func<ScheduledMatch, (int A, int B, int Winner)> score)
    {
        var names = Names(cup.Entrants);
        var played = new Dictionary<int, TournamentRecord>();
        for (int pass = 0; pass < 100; pass++)
        {
            var b = cup.Unfold(names, m => played.GetValueOrDefault(m.Index));
            if (b.Complete)
            {
                return b;
            }

            foreach (var m in b.Steps[^1].Matches)
            {
                var (x, y, w) = score(m);
                played[m.Index] = Record(m, names, x, y, w);
            }
        }

        throw new InvalidOperationException("the tournament does not end");
    }

    private static Bracket Unfold(GroupsKnockout cup, Func<ScheduledMatch, TournamentRecord> record)
    {
        var names = Names(cup.Entrants);
        var b = cup.Unfold(names, record);
        Assert.True(b.Complete);
        return b;
    }

    // The stronger entrant scores 1:0; equal strengths draw 0:0.
    private static Func<ScheduledMatch, (int, int, int)> Strength(params int[] strength) =>
        m => strength[m.Sides[0]] > strength[m.Sides[1]] ? (1, 0, -2) : strength[m.Sides[0]] < strength[m.Sides[1]] ? (0, 1, -2) : (0, 0, -2);

    // A final between entrants 0 and 1: the score of each match, told whether entrant 0 is on team 0; group matches as given too.
    private static Func<ScheduledMatch, (int, int, int)> Scripted(Func<ScheduledMatch, bool, (int, int)> score) => m =>
    {
        bool aFirst = m.Sides[0] == 0;
        var (a, b) = score(m, aFirst);
        return aFirst ? (a, b, -2) : (b, a, -2);
    };

    private static string[] Names(int n) => [.. Enumerable.Range(0, n).Select(i => "e" + i)];

    // A played match; winner −2: the higher score wins, equal scores draw.
    private static TournamentRecord Record(ScheduledMatch m, string[] names, int score0, int score1, int winner)
    {
        int w = winner != -2 ? winner : score0 > score1 ? 0 : score1 > score0 ? 1 : -1;
        return new(m.Index, m.Seed, [names[m.Sides[0]], names[m.Sides[1]]], new MatchResult(m.Index, m.Seed, 100, score0, score1, new long[7], 0, 0, 0, 0f, 0, 0, "ball-grab", [score0, score1], w, "test"), [], []);
    }

    // A round's pairings as "A1 0 v B2 2" (group place, entrant) or "A1 0 bye".
    private static string[] Ties(Bracket b, int round) =>
        [.. b.Rounds[round].Ties.Select(t => t.A is null || t.B is null ? $"{(t.A ?? t.B)!.From} {(t.A ?? t.B)!.Entrant} bye" : $"{t.A.From} {t.A.Entrant} v {t.B.From} {t.B.Entrant}")];
}
