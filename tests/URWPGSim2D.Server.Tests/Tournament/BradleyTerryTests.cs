namespace URWPGSim2D.Server.Tests.Tournament;

/// <summary>The maximum-likelihood fit against cases solved by hand and against a brute-force search of the likelihood.</summary>
public sealed class BradleyTerryTests
{
    [Theory]
    [InlineData(7, 3)]
    [InlineData(1, 9)]
    [InlineData(5, 5)]
    public void TwoEntrantsGetTheLogOddsOfTheirRecord(int wins, int losses)
    {
        // Analytic: with one pair the likelihood p^w (1-p)^l peaks at p = w / n, so θA − θB = ln(w / l).
        var games = Games((0, 1, 1.0, wins), (0, 1, 0.0, losses));
        var theta = BradleyTerry.Fit(2, games, prior: 0);
        Assert.Equal(Math.Log((double)wins / losses), theta[0] - theta[1], 9);
        Assert.Equal(0, theta[0] + theta[1], 12);
    }

    [Fact]
    public void ADrawCountsHalfAWin()
    {
        // 3 wins, 2 draws, 1 loss = 4 of 6: θA − θB = ln(4 / 2); the sides of the pair do not matter.
        var games = Games((0, 1, 1.0, 2), (1, 0, 0.0, 1), (0, 1, 0.5, 1), (1, 0, 0.5, 1), (1, 0, 1.0, 1));
        var theta = BradleyTerry.Fit(2, games, prior: 0);
        Assert.Equal(Math.Log(2), theta[0] - theta[1], 9);
    }

    [Fact]
    public void ThreeEntrantsFitIsTheBruteForceMaximum()
    {
        var games = Games((0, 1, 1.0, 6), (0, 1, 0.0, 2), (1, 2, 1.0, 5), (1, 2, 0.0, 3), (0, 2, 1.0, 4), (0, 2, 0.5, 3), (2, 0, 1.0, 1));
        var theta = BradleyTerry.Fit(3, games, prior: 0);
        var (d1, d2) = GridMaximum(games, 3, prior: 0);
        Assert.True(Math.Abs(d1 - (theta[1] - theta[0])) <= 0.001 && Math.Abs(d2 - (theta[2] - theta[0])) <= 0.001, $"grid {d1} {d2}, fit {theta[1] - theta[0]} {theta[2] - theta[0]}");
        Assert.True(BradleyTerry.LogLikelihood(games, theta, 0) >= BradleyTerry.LogLikelihood(games, [0, d1, d2], 0) - 1e-12);
    }

    [Fact]
    public void ThePriorKeepsAnUnbeatenEntrantFiniteAndIsThePenalisedMaximum()
    {
        // A won all 5 games: no plain maximum exists; with one virtual draw each against a 0 opponent the
        // penalised likelihood has one, found here by brute force over (θA, θB).
        var games = Games((0, 1, 1.0, 5));
        var theta = BradleyTerry.Fit(2, games, prior: 1, centre: false);
        Assert.True(double.IsFinite(theta[0]) && theta[0] > 0 && theta[1] < 0);
        var (a, b) = GridMaximum(games, 2, prior: 1);
        Assert.InRange(theta[0], a - 0.001, a + 0.001);
        Assert.InRange(theta[1], b - 0.001, b + 0.001);
        // Symmetric record: θB = −θA exactly.
        Assert.Equal(-theta[0], theta[1], 9);
    }

    [Theory]
    [InlineData(0.0)]
    [InlineData(1.0)]
    public void NewtonAndTheMinorisationIterationFindTheSameMaximum(double prior)
    {
        var games = PairRatingsTests.Simulate([1700, 1550, 1500, 1400, 1300, 1250], 3, new Random(9), drawChance: 0.2);
        var wins = new double[6];
        var pairs = new double[36];
        foreach (var g in games)
        {
            wins[g.A] += g.ScoreA;
            wins[g.B] += 1 - g.ScoreA;
            pairs[(g.A * 6) + g.B]++;
            pairs[(g.B * 6) + g.A]++;
        }

        var newton = BradleyTerry.Fit(6, games, prior, centre: false);
        var mm = BradleyTerry.Minorise(6, wins, pairs, prior, new double[6]);
        if (prior == 0)
        {
            BradleyTerry.Centre(newton);
            BradleyTerry.Centre(mm);
        }

        for (int i = 0; i < 6; i++)
        {
            Assert.Equal(mm[i], newton[i], 7);
        }
    }

    [Fact]
    public void BadGamesAreRefused()
    {
        Assert.Throws<ArgumentException>(() => BradleyTerry.Fit(2, [new Game(0, 2, 1)], 0));
        Assert.Throws<ArgumentException>(() => BradleyTerry.Fit(2, [new Game(1, 1, 1)], 0));
        Assert.Throws<ArgumentException>(() => BradleyTerry.Fit(2, [new Game(0, 1, 0.3)], 0));
        Assert.Throws<ArgumentException>(() => BradleyTerry.Fit(2, [new Game(0, 1, 1)], -1));
    }

    internal static List<Game> Games(params (int A, int B, double Score, int Count)[] groups)
    {
        var games = new List<Game>();
        foreach (var (a, b, score, count) in groups)
        {
            for (int k = 0; k < count; k++)
            {
                games.Add(new Game(a, b, score));
            }
        }

        return games;
    }

    // Brute force over the two free coordinates, (θ1, θ2) with θ0 = 0 for 3 entrants or (θ0, θ1) for 2 (the prior
    // anchors them): a 0.02 grid over [−4, 4]², then a 0.001 grid around its best point.
    private static (double X, double Y) GridMaximum(List<Game> games, int entrants, double prior)
    {
        var (x, y) = Search(games, entrants, prior, 0, 0, 0.02, 200);
        return Search(games, entrants, prior, x, y, 0.001, 40);
    }

    private static (double X, double Y) Search(List<Game> games, int entrants, double prior, double cx, double cy, double step, int half)
    {
        double bestValue = double.NegativeInfinity, bx = 0, by = 0;
        for (int i = -half; i <= half; i++)
        {
            for (int j = -half; j <= half; j++)
            {
                double x = cx + (i * step), y = cy + (j * step);
                double[] theta = entrants == 3 ? [0, x, y] : [x, y];
                double value = BradleyTerry.LogLikelihood(games, theta, prior);
                if (value > bestValue)
                {
                    (bestValue, bx, by) = (value, x, y);
                }
            }
        }

        return (bx, by);
    }
}
