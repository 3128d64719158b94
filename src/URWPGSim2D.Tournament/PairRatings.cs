namespace URWPGSim2D.Tournament;

/// <summary>
/// Ratings of the entrants of a two-team tournament: the Bradley–Terry fit (draws half a win, one
/// virtual draw of each entrant against a 1500-rated opponent, see <see cref="BradleyTerry"/>) on
/// the Elo scale, 1500 + 400·log₁₀(odds), shifted so that the ratings average 1500; and 95 %
/// percentile intervals from a bootstrap over the games: each replicate draws, for every pair of
/// entrants, as many of that pair's games as it played, with replacement, and is fitted again. The
/// replicates come from a generator with a fixed seed, so the same games give the same numbers.
/// </summary>
internal static class PairRatings
{
    /// <summary>Virtual draws of every entrant against a 1500-rated opponent.</summary>
    public const double Prior = 1;

    /// <summary>The average rating.</summary>
    public const double Mean = 1500;

    /// <summary>Bootstrap replicates of the standings.</summary>
    public const int Replicates = 1000;

    /// <summary>The seed of the bootstrap's generator.</summary>
    public const ulong Seed = 1;

    /// <summary>The ratings and their intervals.</summary>
    /// <param name="entrants">Number of entrants.</param>
    /// <param name="games">The games, in a fixed order (the schedule's).</param>
    /// <param name="replicates">Bootstrap replicates, ≥ 1.</param>
    /// <param name="seed">The bootstrap's seed.</param>
    public static (double[] Ratings, Interval[] Intervals) Compute(int entrants, IReadOnlyList<Game> games, int replicates = Replicates, ulong seed = Seed)
    {
        ArgumentOutOfRangeException.ThrowIfLessThan(replicates, 1);
        var raw = BradleyTerry.Fit(entrants, games, Prior, centre: false);
        var ratings = Scale(raw);

        // The strata: each unordered pair's games, in order.
        var strata = new Dictionary<(int, int), List<Game>>();
        var order = new List<(int, int)>();
        foreach (var g in games)
        {
            var key = g.A < g.B ? (g.A, g.B) : (g.B, g.A);
            if (!strata.TryGetValue(key, out var list))
            {
                strata[key] = list = [];
                order.Add(key);
            }

            list.Add(g);
        }

        var random = new SplitMix64(seed);
        var samples = new double[entrants][];
        for (int i = 0; i < entrants; i++)
        {
            samples[i] = new double[replicates];
        }

        var wins = new double[entrants];
        var pairs = new double[entrants * entrants];
        for (int r = 0; r < replicates; r++)
        {
            Array.Clear(wins);
            Array.Clear(pairs);
            foreach (var key in order)
            {
                var list = strata[key];
                for (int k = 0; k < list.Count; k++)
                {
                    var g = list[random.Below(list.Count)];
                    wins[g.A] += g.ScoreA;
                    wins[g.B] += 1 - g.ScoreA;
                    pairs[(g.A * entrants) + g.B]++;
                    pairs[(g.B * entrants) + g.A]++;
                }
            }

            var replicate = Scale(BradleyTerry.Solve(entrants, wins, pairs, Prior, raw));
            for (int i = 0; i < entrants; i++)
            {
                samples[i][r] = replicate[i];
            }
        }

        var intervals = new Interval[entrants];
        for (int i = 0; i < entrants; i++)
        {
            intervals[i] = Interval.Percentile(samples[i]);
        }

        return (ratings, intervals);
    }

    /// <summary>Strengths (not centred) as ratings averaging <see cref="Mean"/>.</summary>
    public static double[] Scale(double[] theta)
    {
        var centred = (double[])theta.Clone();
        BradleyTerry.Centre(centred);
        for (int i = 0; i < centred.Length; i++)
        {
            centred[i] = Mean + (BradleyTerry.PointsPerUnit * centred[i]);
        }

        return centred;
    }
}
