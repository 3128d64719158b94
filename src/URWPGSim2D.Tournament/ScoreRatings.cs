namespace URWPGSim2D.Tournament;

/// <summary>
/// Standings numbers of a one-team item: each entrant's mean score and mean match length (the
/// item's time tie-break: an item that ends when its task is done ends sooner for the better
/// run), and a 95 % percentile interval of the mean score from a bootstrap over the entrant's own
/// matches (<see cref="PairRatings.Replicates"/> replicates, generator seeded with <see cref="PairRatings.Seed"/>).
/// </summary>
internal static class ScoreRatings
{
    /// <summary>Mean score, its interval and mean cycles of one entrant's matches.</summary>
    /// <param name="matches">(score, cycles) of each match, in schedule order; at least one.</param>
    /// <param name="random">The bootstrap's generator (shared by the entrants in standings order, so the bytes are fixed).</param>
    /// <param name="replicates">Bootstrap replicates, ≥ 1.</param>
    public static (double Score, Interval Interval, double Cycles) Compute(IReadOnlyList<(double Score, int Cycles)> matches, ref SplitMix64 random, int replicates = PairRatings.Replicates)
    {
        if (matches.Count == 0)
        {
            throw new ArgumentException("an entrant without matches has no mean score", nameof(matches));
        }

        double sum = 0, cycles = 0;
        foreach (var (score, length) in matches)
        {
            sum += score;
            cycles += length;
        }

        var means = new double[replicates];
        for (int r = 0; r < replicates; r++)
        {
            double s = 0;
            for (int k = 0; k < matches.Count; k++)
            {
                s += matches[random.Below(matches.Count)].Score;
            }

            means[r] = s / matches.Count;
        }

        return (sum / matches.Count, Interval.Percentile(means), cycles / matches.Count);
    }
}
