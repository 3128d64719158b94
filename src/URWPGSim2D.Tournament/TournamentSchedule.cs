namespace URWPGSim2D.Tournament;

/// <summary>
/// The deterministic schedule of a tournament of E entrants over N seeds S, S + 1, … S + N − 1,
/// seed by seed (so a tournament stopped early has played every pairing about as often):
/// <list type="bullet">
/// <item>one-team item: every entrant once per seed, in entrant order (E·N matches);</item>
/// <item>two-team item: every ordered pair (i, j), i ≠ j, once per seed (i on team 0, j on team 1;
/// both sides of the field for each pair, on the same seed), pairs in lexicographic order (E(E − 1)·N matches);</item>
/// <item>T ≥ 3 teams: per seed, E rotations: rotation r puts entrant (r + t) mod E on team t, so every
/// entrant plays every team's side once per seed and the teams meet in cyclic groups (E·N matches; E ≥ T).</item>
/// </list>
/// </summary>
public sealed class TournamentSchedule
{
    /// <summary>Builds the schedule.</summary>
    /// <param name="teams">Teams per match, ≥ 1.</param>
    /// <param name="entrants">Entrants, ≥ 1 (≥ teams when teams ≥ 2).</param>
    /// <param name="seeds">Seeds, ≥ 1.</param>
    /// <param name="firstSeed">The first seed.</param>
    /// <exception cref="ArgumentException">A count out of range, or too many matches (more than <see cref="MaximumMatches"/>).</exception>
    public TournamentSchedule(int teams, int entrants, int seeds, ulong firstSeed)
    {
        if (teams < 1)
        {
            throw new ArgumentException($"teams must be >= 1, got {teams}", nameof(teams));
        }

        if (entrants < Math.Max(teams, 1) || (teams >= 2 && entrants < 2))
        {
            throw new ArgumentException($"a {teams}-team item needs at least {Math.Max(teams, teams >= 2 ? 2 : 1)} entrants, got {entrants}", nameof(entrants));
        }

        if (seeds < 1)
        {
            throw new ArgumentException($"seeds must be >= 1, got {seeds}", nameof(seeds));
        }

        long perSeed = teams == 2 ? (long)entrants * (entrants - 1) : entrants;
        if (perSeed * seeds > MaximumMatches)
        {
            throw new ArgumentException($"{entrants} entrants over {seeds} seeds make {perSeed * seeds} matches, more than {MaximumMatches}", nameof(seeds));
        }

        if (firstSeed > long.MaxValue - (ulong)seeds)
        {
            throw new ArgumentException($"seeds from {firstSeed} would go beyond {long.MaxValue}", nameof(firstSeed));
        }

        Teams = teams;
        Entrants = entrants;
        Seeds = seeds;
        FirstSeed = firstSeed;
        var matches = new List<ScheduledMatch>((int)(perSeed * seeds));
        for (int s = 0; s < seeds; s++)
        {
            ulong seed = firstSeed + (ulong)s;
            if (teams == 2)
            {
                for (int i = 0; i < entrants; i++)
                {
                    for (int j = 0; j < entrants; j++)
                    {
                        if (i != j)
                        {
                            matches.Add(new ScheduledMatch(matches.Count, seed, [i, j]));
                        }
                    }
                }

                continue;
            }

            for (int r = 0; r < entrants; r++)
            {
                var sides = new int[teams];
                for (int t = 0; t < teams; t++)
                {
                    sides[t] = (r + t) % entrants;
                }

                matches.Add(new ScheduledMatch(matches.Count, seed, sides));
            }
        }

        Matches = matches;
    }

    /// <summary>Most matches of one tournament.</summary>
    public const int MaximumMatches = 10_000_000;

    /// <summary>Teams per match.</summary>
    public int Teams { get; }

    /// <summary>Entrants.</summary>
    public int Entrants { get; }

    /// <summary>Seeds.</summary>
    public int Seeds { get; }

    /// <summary>The first seed.</summary>
    public ulong FirstSeed { get; }

    /// <summary>The matches, by index.</summary>
    public IReadOnlyList<ScheduledMatch> Matches { get; }
}
