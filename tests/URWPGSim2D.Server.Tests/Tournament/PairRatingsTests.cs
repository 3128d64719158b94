using Xunit.Abstractions;

namespace URWPGSim2D.Server.Tests.Tournament;

/// <summary>
/// The ratings and their bootstrap intervals against tournaments simulated from known strengths
/// (Bradley–Terry games drawn with a seeded generator): the order comes back, equal entrants are
/// not separated, and the 95 % intervals hold the true ratings about 95 % of the time.
/// </summary>
public sealed class PairRatingsTests(ITestOutputHelper output)
{
    [Fact]
    public void KnownStrengthsComeBackInOrder()
    {
        double[] truth = [1800, 1650, 1500, 1350, 1200];
        var random = new Random(11);
        var games = Simulate(truth, 20, random, drawChance: 0.2);
        var (ratings, intervals) = PairRatings.Compute(truth.Length, games, replicates: 300);
        var order = Enumerable.Range(0, truth.Length).OrderByDescending(i => ratings[i]).ToArray();
        Assert.Equal([0, 1, 2, 3, 4], order);
        Assert.Equal(1500, ratings.Average(), 9);
        Assert.False(intervals[0].Overlaps(intervals[4]));
        for (int i = 0; i < truth.Length; i++)
        {
            Assert.True(intervals[i].Low <= ratings[i] && ratings[i] <= intervals[i].High);
        }
    }

    [Fact]
    public void IdenticalEntrantsGetOverlappingIntervals()
    {
        double[] truth = [1500, 1500, 1500, 1500];
        var games = Simulate(truth, 10, new Random(5), drawChance: 0.3);
        var (ratings, intervals) = PairRatings.Compute(truth.Length, games, replicates: 300);
        for (int i = 0; i < truth.Length; i++)
        {
            Assert.True(intervals[i].Contains(1500), $"entrant {i}: {intervals[i]}");
            for (int j = 0; j < truth.Length; j++)
            {
                Assert.True(intervals[i].Overlaps(intervals[j]), $"{i} {intervals[i]} vs {j} {intervals[j]}");
            }
        }

        Assert.True(ratings.Max() - ratings.Min() < 200);
    }

    [Fact]
    public void NinetyFivePercentIntervalsCoverTheTruthAboutNinetyFivePercentOfTheTime()
    {
        // 200 tournaments of 5 entrants, 12 games per ordered pair (no draws: the games follow the model
        // exactly). Each interval's coverage of the true centred rating is counted; over 1,000 intervals
        // a true 95 % gives 95 ± 1.4 % (one standard error 0.7 %); the percentile bootstrap of a
        // maximum-likelihood fit runs a little narrow on small samples, so the band is 90-98 %.
        double[] truth = [1700, 1600, 1500, 1450, 1250];
        double mean = truth.Average();
        int covered = 0, total = 0;
        var random = new Random(2026);
        for (int t = 0; t < 200; t++)
        {
            var games = Simulate(truth, 6, random, drawChance: 0);
            var (_, intervals) = PairRatings.Compute(truth.Length, games, replicates: 200, seed: (ulong)t + 1);
            for (int i = 0; i < truth.Length; i++)
            {
                covered += intervals[i].Contains(truth[i] - mean + PairRatings.Mean) ? 1 : 0;
                total++;
            }
        }

        double coverage = (double)covered / total;
        output.WriteLine($"coverage {covered} of {total} = {coverage:P1}");
        Assert.InRange(coverage, 0.90, 0.98);
    }

    [Fact]
    public void TheSameGamesGiveTheSameNumbers()
    {
        var games = Simulate([1600, 1500, 1400], 5, new Random(3), drawChance: 0.2);
        var a = PairRatings.Compute(3, games);
        var b = PairRatings.Compute(3, games);
        Assert.Equal(a.Ratings, b.Ratings);
        Assert.Equal(a.Intervals, b.Intervals);
    }

    /// <summary>Every ordered pair plays <paramref name="perSide"/> games (so 2·perSide per pair): a draw with the given chance, else a Bradley–Terry win.</summary>
    internal static List<Game> Simulate(double[] ratings, int perSide, Random random, double drawChance)
    {
        var games = new List<Game>();
        for (int k = 0; k < perSide; k++)
        {
            for (int i = 0; i < ratings.Length; i++)
            {
                for (int j = 0; j < ratings.Length; j++)
                {
                    if (i == j)
                    {
                        continue;
                    }

                    double p = 1 / (1 + Math.Pow(10, (ratings[j] - ratings[i]) / 400));
                    double score = random.NextDouble() < drawChance ? 0.5 : random.NextDouble() < p ? 1 : 0;
                    games.Add(new Game(i, j, score));
                }
            }
        }

        return games;
    }
}
