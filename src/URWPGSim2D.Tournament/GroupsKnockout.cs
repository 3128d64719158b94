namespace URWPGSim2D.Tournament;

/// <summary>
/// The group stage and knockout format of a two-team item (<c>tournament --format groups-knockout</c>):
/// <list type="bullet">
/// <item>the entrants, in seeding order (the entrant order, or <c>--seeding</c>), are dealt into G groups
/// by snake seeding (A, B, …, G, G, …, B, A, A, …), so group sizes differ by one at most;</item>
/// <item>each group is a round robin: every ordered pair of its entrants (both sides of the field) on each
/// of the N seeds S … S + N − 1, ranked by the points table (<see cref="PointsTable"/>);</item>
/// <item>the top K of each group go into a single-elimination bracket, seeded place by place in group order
/// (A1, B1, …, A2, B2, …) on the standard bracket (seed 1 meets the last seed, …), the seeds beyond the
/// qualifiers being byes for the best seeds; where two entrants of one group would meet in the first round,
/// the weaker swaps with the weaker of the next pair it can swap with (so A1 meets B2 and B1 meets A2);</item>
/// <item>a knockout pairing (a tie) plays both sides of the field on each of its seeds, S + N, S + N + 1, …
/// (N seeds, the final F): the entrant with more wins goes on (each match won as the item decides it, with the
/// item's own tie rules, such as water polo's extra time and penalties), then the one with the better goal
/// difference over the tie; a tie still level plays a further seed (both sides) and is judged again, at most
/// <see cref="MaximumFurtherSeeds"/> times; then the better seed goes on.</item>
/// </list>
/// The knockout's matches are known only as the results come in: <see cref="Unfold"/> lays the tournament
/// out from the results so far, step by step, up to the first step whose matches are not all played. Match
/// indices are the group stage's first, then each step's in order, so they depend only on the results.
/// </summary>
public sealed class GroupsKnockout
{
    /// <summary>The further seeds a level knockout tie plays at most before the better seed goes on.</summary>
    public const int MaximumFurtherSeeds = 3;

    /// <summary>Lays out the groups and the group stage.</summary>
    /// <param name="entrants">Entrants, ≥ 2 per group.</param>
    /// <param name="groups">Groups G, ≥ 1.</param>
    /// <param name="advance">Entrants K of each group into the knockout, 1 … the smallest group's size; G·K ≥ 2.</param>
    /// <param name="seeds">Seeds N of each group pairing and of each knockout tie but the final, ≥ 1.</param>
    /// <param name="finalSeeds">Seeds F of the final, ≥ 1.</param>
    /// <param name="firstSeed">The first seed S.</param>
    /// <param name="seeding">The entrants in seeding order (a permutation of 0 … E − 1), or null for the entrant order.</param>
    /// <exception cref="ArgumentException">A count out of range, named by its option.</exception>
    public GroupsKnockout(int entrants, int groups, int advance, int seeds, int finalSeeds, ulong firstSeed, IReadOnlyList<int>? seeding = null)
    {
        if (groups < 1 || entrants < 2 * groups)
        {
            throw new ArgumentException($"--groups {groups}: {groups} groups need at least {2 * Math.Max(groups, 1)} entrants (two a group), got {entrants}");
        }

        int smallest = entrants / groups;
        if (advance < 1 || advance > smallest)
        {
            throw new ArgumentException($"--advance {advance}: must be 1 … {smallest}, the smallest group's size");
        }

        if (groups * advance < 2)
        {
            throw new ArgumentException($"--advance {advance}: one group needs at least 2 entrants into the knockout");
        }

        if (seeds < 1 || finalSeeds < 1)
        {
            throw new ArgumentException($"--final-seeds {finalSeeds}: must be 1 or more");
        }

        if (firstSeed > (ulong)long.MaxValue - (ulong)seeds - (ulong)Math.Max(seeds, finalSeeds) - MaximumFurtherSeeds)
        {
            throw new ArgumentException($"--seed {firstSeed}: the knockout's seeds would go beyond {long.MaxValue}");
        }

        var order = seeding?.ToArray() ?? Enumerable.Range(0, entrants).ToArray();
        if (order.Length != entrants || order.Distinct().Count() != entrants || order.Any(e => e < 0 || e >= entrants))
        {
            throw new ArgumentException("--seeding: must name every entrant once");
        }

        var members = new List<int>[groups];
        for (int g = 0; g < groups; g++)
        {
            members[g] = [];
        }

        for (int k = 0; k < entrants; k++)
        {
            int row = k / groups, column = k % groups;
            members[row % 2 == 0 ? column : groups - 1 - column].Add(order[k]);
        }

        long perSeed = members.Sum(m => (long)m.Count * (m.Count - 1));
        if (perSeed * seeds > TournamentSchedule.MaximumMatches)
        {
            throw new ArgumentException($"--seeds {seeds}: the group stage would have {perSeed * seeds} matches, more than {TournamentSchedule.MaximumMatches}");
        }

        var matches = new List<ScheduledMatch>((int)(perSeed * seeds));
        var groupOf = new int[entrants];
        for (int g = 0; g < groups; g++)
        {
            foreach (int e in members[g])
            {
                groupOf[e] = g;
            }
        }

        for (int s = 0; s < seeds; s++)
        {
            ulong seed = firstSeed + (ulong)s;
            for (int g = 0; g < groups; g++)
            {
                foreach (int i in members[g])
                {
                    foreach (int j in members[g])
                    {
                        if (i != j)
                        {
                            matches.Add(new ScheduledMatch(matches.Count, seed, [i, j]));
                        }
                    }
                }
            }
        }

        Entrants = entrants;
        Groups = members;
        GroupOf = groupOf;
        Advance = advance;
        Seeds = seeds;
        FinalSeeds = finalSeeds;
        FirstSeed = firstSeed;
        GroupMatches = matches;
        BracketSize = 1;
        while (BracketSize < groups * advance)
        {
            BracketSize *= 2;
        }
    }

    /// <summary>Entrants.</summary>
    public int Entrants { get; }

    /// <summary>Per group (A first), its entrants in seeding order.</summary>
    public IReadOnlyList<IReadOnlyList<int>> Groups { get; }

    /// <summary>Per entrant, its group.</summary>
    public IReadOnlyList<int> GroupOf { get; }

    /// <summary>Entrants of each group into the knockout.</summary>
    public int Advance { get; }

    /// <summary>Seeds of each group pairing and of each knockout tie but the final.</summary>
    public int Seeds { get; }

    /// <summary>Seeds of the final.</summary>
    public int FinalSeeds { get; }

    /// <summary>The first seed of the group stage; the knockout's start at <see cref="FirstSeed"/> + <see cref="Seeds"/>.</summary>
    public ulong FirstSeed { get; }

    /// <summary>The group stage's matches: seed by seed, group by group, every ordered pair of the group's entrants.</summary>
    public IReadOnlyList<ScheduledMatch> GroupMatches { get; }

    /// <summary>The bracket's size: the smallest power of two that holds every qualifier.</summary>
    public int BracketSize { get; }

    /// <summary>Matches of the whole tournament when no knockout tie needs a further seed.</summary>
    public int PlannedMatches => GroupMatches.Count + (2 * Seeds * (Groups.Count * Advance - 2)) + (2 * FinalSeeds);

    /// <summary>A group's name: A … Z, then G27, G28, ….</summary>
    public static string GroupName(int group) => group < 26 ? ((char)('A' + group)).ToString() : "G" + (group + 1).ToString(CultureInfo.InvariantCulture);

    /// <summary>A knockout round's name by its ties: <c>final</c>, <c>semi-finals</c>, <c>quarter-finals</c>, <c>round of 16</c>, ….</summary>
    public static string RoundName(int ties) => ties switch
    {
        1 => "final",
        2 => "semi-finals",
        4 => "quarter-finals",
        _ => "round of " + (2 * ties).ToString(CultureInfo.InvariantCulture),
    };

    /// <summary>The seeds of a bracket of <paramref name="size"/> (a power of two) by position: 1, size, …, so that seed i meets seed size + 1 − i and the best seeds meet last.</summary>
    public static IReadOnlyList<int> BracketOrder(int size)
    {
        var order = new List<int> { 1 };
        for (int n = 1; n < size; n *= 2)
        {
            order = [.. order.SelectMany(s => new[] { s, (2 * n) + 1 - s })];
        }

        return order;
    }

    /// <summary>
    /// Lays the tournament out from the results so far: the group stage, then the knockout round by round,
    /// up to and with the first step whose matches are not all played (their records are null).
    /// </summary>
    /// <param name="names">The entrants' names, by index.</param>
    /// <param name="result">A scheduled match's record, or null when it has not been played.</param>
    public Bracket Unfold(IReadOnlyList<string> names, Func<ScheduledMatch, TournamentRecord?> result)
    {
        var all = new List<ScheduledMatch>(GroupMatches);
        var steps = new List<CupStep> { new("group stage", GroupMatches) };
        var records = new Dictionary<int, TournamentRecord>();
        var stages = new Dictionary<int, (string Stage, string Round)>();
        foreach (var m in GroupMatches)
        {
            stages[m.Index] = ("group", GroupName(GroupOf[m.Sides[0]]));
        }

        bool Fill(IEnumerable<ScheduledMatch> step)
        {
            bool complete = true;
            foreach (var m in step)
            {
                if (result(m) is { } r)
                {
                    records[m.Index] = r;
                }
                else
                {
                    complete = false;
                }
            }

            return complete;
        }

        Bracket Partial(List<CupGroup> groups, List<CupRound> rounds, CupSlot? champion) => new(groups, rounds, champion, steps, all, records, stages);

        if (!Fill(GroupMatches))
        {
            return Partial([], [], null);
        }

        var tables = new List<CupGroup>(Groups.Count);
        for (int g = 0; g < Groups.Count; g++)
        {
            var group = Groups[g];
            var own = GroupMatches.Where(m => GroupOf[m.Sides[0]] == g).Select(m => records[m.Index]).ToList();
            var table = PointsTable.Compute(own, [.. group.Select(e => names[e])]);
            tables.Add(new CupGroup(GroupName(g), group, [.. table.Select(p => p with { Entrant = group[p.Entrant] })]));
        }

        var slots = FirstRound(tables);
        var rounds = new List<CupRound>();
        var knockout = FirstSeed + (ulong)Seeds;
        while (true)
        {
            int count = slots.Count / 2;
            string name = RoundName(count);
            int seeds = count == 1 ? FinalSeeds : Seeds;
            var ties = new List<TieState>(count);
            var step = new List<ScheduledMatch>();
            for (int k = 0; k < count; k++)
            {
                var tie = new TieState(rounds.Count, k, slots[2 * k], slots[(2 * k) + 1]);
                ties.Add(tie);
                if (tie.A is not null && tie.B is not null)
                {
                    for (int s = 0; s < seeds; s++)
                    {
                        Schedule(tie, knockout + (ulong)s, step, all, stages, name);
                    }
                }
            }

            steps.Add(new CupStep(name, step));
            bool complete = Fill(step);
            for (int further = 0; complete; further++)
            {
                var level = new List<TieState>();
                foreach (var tie in ties)
                {
                    if (!Decide(tie, names, records, further == MaximumFurtherSeeds))
                    {
                        level.Add(tie);
                    }
                }

                if (level.Count == 0)
                {
                    break;
                }

                var more = new List<ScheduledMatch>();
                foreach (var tie in level)
                {
                    Schedule(tie, knockout + (ulong)seeds + (ulong)further, more, all, stages, name);
                }

                steps.Add(new CupStep(string.Create(CultureInfo.InvariantCulture, $"{name}, further seed {further + 1}"), more));
                complete = Fill(more);
            }

            rounds.Add(new CupRound(name, [.. ties.Select(t => t.ToTie())]));
            if (!complete)
            {
                return Partial(tables, rounds, null);
            }

            if (count == 1)
            {
                return Partial(tables, rounds, ties[0].Winner);
            }

            slots = [.. ties.Select(t => t.Winner)];
        }
    }

    // The qualifiers on the first round's positions (null: a bye), the same group kept apart where it can be.
    private List<CupSlot?> FirstRound(List<CupGroup> tables)
    {
        var qualifiers = new List<CupSlot>();
        for (int place = 0; place < Advance; place++)
        {
            for (int g = 0; g < tables.Count; g++)
            {
                qualifiers.Add(new CupSlot(tables[g].Table[place].Entrant, qualifiers.Count + 1, GroupName(g) + (place + 1).ToString(CultureInfo.InvariantCulture)));
            }
        }

        var slots = BracketOrder(BracketSize).Select(s => s <= qualifiers.Count ? qualifiers[s - 1] : null).ToList();
        int pairs = slots.Count / 2;
        bool Apart(CupSlot? a, CupSlot? b) => a is null || b is null || GroupOf[a.Entrant] != GroupOf[b.Entrant];
        for (int k = 0; k < pairs; k++)
        {
            if (Apart(slots[2 * k], slots[(2 * k) + 1]))
            {
                continue;
            }

            for (int step = 1; step < pairs; step++)
            {
                int m = (k + step) % pairs;
                var a = slots[2 * k];
                var b = slots[(2 * k) + 1];
                var c = slots[2 * m];
                var d = slots[(2 * m) + 1];
                if (d is not null && c is not null && Apart(a, d) && Apart(c, b))
                {
                    slots[(2 * k) + 1] = d;
                    slots[(2 * m) + 1] = b;
                    break;
                }
            }
        }

        return slots;
    }

    // Both sides of the field of a tie on one seed: the better seed on team 0 first.
    private static void Schedule(TieState tie, ulong seed, List<ScheduledMatch> step, List<ScheduledMatch> all, Dictionary<int, (string, string)> stages, string round)
    {
        foreach (var sides in new[] { new[] { tie.A!.Entrant, tie.B!.Entrant }, [tie.B!.Entrant, tie.A!.Entrant] })
        {
            var m = new ScheduledMatch(all.Count, seed, sides);
            all.Add(m);
            step.Add(m);
            tie.Matches.Add(m);
            stages[m.Index] = ("knockout", round);
        }
    }

    // Judges a tie on its matches so far: wins, then goal difference; a bye goes on; last, the better seed. False: still level.
    private static bool Decide(TieState tie, IReadOnlyList<string> names, Dictionary<int, TournamentRecord> records, bool last)
    {
        if (tie.A is null || tie.B is null)
        {
            tie.Winner = tie.A ?? tie.B;
            tie.DecidedBy = "bye";
            return true;
        }

        int winsA = 0, winsB = 0, goalsA = 0, goalsB = 0;
        foreach (var m in tie.Matches)
        {
            var r = records[m.Index];
            bool aFirst = r.Entrants[0] == names[tie.A.Entrant];
            if (Standings.Outcome(r, 0, 1) is { } score)
            {
                double forA = aFirst ? score : 1 - score;
                winsA += forA == 1 ? 1 : 0;
                winsB += forA == 0 ? 1 : 0;
            }

            int g0 = Goals(r, 0), g1 = Goals(r, 1);
            goalsA += aFirst ? g0 : g1;
            goalsB += aFirst ? g1 : g0;
        }

        (tie.WinsA, tie.WinsB, tie.GoalsA, tie.GoalsB) = (winsA, winsB, goalsA, goalsB);
        (tie.Winner, tie.DecidedBy) =
            winsA != winsB ? (winsA > winsB ? tie.A : tie.B, "wins")
            : goalsA != goalsB ? (goalsA > goalsB ? tie.A : tie.B, "goal difference")
            : last ? (tie.A.Seed < tie.B.Seed ? tie.A : tie.B, "seeding")
            : ((CupSlot?)null, (string?)null);
        return tie.Winner is not null;
    }

    /// <summary>A side's goals in a match: its item score where the item keeps one, else its goals; none in a forfeit.</summary>
    public static int Goals(TournamentRecord r, int side) => r.Result switch
    {
        null => 0,
        { Scores: { } s } => side < s.Length ? s[side] : 0,
        { } result => side == 0 ? result.Goals0 : side == 1 ? result.Goals1 : 0,
    };

    private sealed class TieState(int round, int pair, CupSlot? a, CupSlot? b)
    {
        public CupSlot? A { get; } = a;

        public CupSlot? B { get; } = b;

        public List<ScheduledMatch> Matches { get; } = [];

        public int WinsA { get; set; }

        public int WinsB { get; set; }

        public int GoalsA { get; set; }

        public int GoalsB { get; set; }

        public CupSlot? Winner { get; set; }

        public string? DecidedBy { get; set; }

        public CupTie ToTie() => new(round, pair, A, B, Matches, WinsA, WinsB, GoalsA, GoalsB, Winner, DecidedBy);
    }
}

/// <summary>A group's final table.</summary>
/// <param name="Name">A, B, ….</param>
/// <param name="Entrants">Its entrants in seeding order.</param>
/// <param name="Table">Its points table, best first (<see cref="PointsRow.Entrant"/>: the tournament's entrant index).</param>
public sealed record CupGroup(string Name, IReadOnlyList<int> Entrants, IReadOnlyList<PointsRow> Table);

/// <summary>A qualifier's place in the bracket.</summary>
/// <param name="Entrant">The entrant's index.</param>
/// <param name="Seed">Its bracket seed, 1 best.</param>
/// <param name="From">Its group and place there, e.g. <c>A1</c>.</param>
public sealed record CupSlot(int Entrant, int Seed, string From);

/// <summary>One knockout pairing.</summary>
/// <param name="Round">The round, 0 first.</param>
/// <param name="Pair">Its place in the round, 0 first (the winners of pairs 2k and 2k + 1 meet next).</param>
/// <param name="A">The better-placed side (team 0 first), or null for a bye.</param>
/// <param name="B">The other side, or null for a bye.</param>
/// <param name="Matches">Its matches, both sides of the field on each seed, in order.</param>
/// <param name="WinsA">Matches A won.</param>
/// <param name="WinsB">Matches B won.</param>
/// <param name="GoalsA">A's goals over the matches.</param>
/// <param name="GoalsB">B's goals over the matches.</param>
/// <param name="Winner">Who goes on, or null while it is not decided.</param>
/// <param name="DecidedBy"><c>wins</c>, <c>goal difference</c>, <c>seeding</c> or <c>bye</c>; null while not decided.</param>
public sealed record CupTie(int Round, int Pair, CupSlot? A, CupSlot? B, IReadOnlyList<ScheduledMatch> Matches, int WinsA, int WinsB, int GoalsA, int GoalsB, CupSlot? Winner, string? DecidedBy);

/// <summary>A knockout round.</summary>
/// <param name="Name"><c>final</c>, <c>semi-finals</c>, ….</param>
/// <param name="Ties">Its pairings in bracket order.</param>
public sealed record CupRound(string Name, IReadOnlyList<CupTie> Ties);

/// <summary>A step of the tournament: matches that can be played once the steps before are.</summary>
/// <param name="Label"><c>group stage</c>, a round's name, or <c>NAME, further seed K</c>.</param>
/// <param name="Matches">Its matches.</param>
public sealed record CupStep(string Label, IReadOnlyList<ScheduledMatch> Matches);

/// <summary>A group stage and knockout as far as the results lay it out (<see cref="GroupsKnockout.Unfold"/>).</summary>
/// <param name="Groups">The groups' tables, once the group stage is played (else empty).</param>
/// <param name="Rounds">The knockout rounds laid out so far.</param>
/// <param name="Champion">The winner of the final, once it is decided.</param>
/// <param name="Steps">The steps in order; the last may have matches not played.</param>
/// <param name="Matches">Every scheduled match so far, by index.</param>
/// <param name="Records">The records of the scheduled matches played, by index.</param>
/// <param name="Stages">Per match index, its stage (<c>group</c> or <c>knockout</c>) and round (the group's name or the round's).</param>
public sealed record Bracket(
    IReadOnlyList<CupGroup> Groups, IReadOnlyList<CupRound> Rounds, CupSlot? Champion, IReadOnlyList<CupStep> Steps,
    IReadOnlyList<ScheduledMatch> Matches, IReadOnlyDictionary<int, TournamentRecord> Records, IReadOnlyDictionary<int, (string Stage, string Round)> Stages)
{
    /// <summary>Whether every step is played and the champion known.</summary>
    public bool Complete => Champion is not null;

    /// <summary>The furthest an entrant went: <c>champion</c>, the name of the round it lost (e.g. <c>final</c>), or <c>group</c> when it did not qualify.</summary>
    public string Reached(int entrant)
    {
        if (Champion?.Entrant == entrant)
        {
            return "champion";
        }

        string reached = "group";
        foreach (var round in Rounds)
        {
            if (round.Ties.Any(t => t.A?.Entrant == entrant || t.B?.Entrant == entrant))
            {
                reached = round.Name;
            }
        }

        return reached;
    }
}
