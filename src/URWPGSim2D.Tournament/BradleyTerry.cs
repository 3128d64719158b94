namespace URWPGSim2D.Tournament;

/// <summary>
/// The Bradley–Terry model of two-team games, fitted by maximum likelihood: entrant i has a
/// strength θᵢ and beats j with probability 1 / (1 + e^(θⱼ − θᵢ)). A draw counts as half a win
/// and half a loss (its likelihood is p^½ (1 − p)^½). So that an entrant who won or lost every
/// game still gets a finite strength, each entrant may be given <c>prior</c> virtual draws against
/// a fixed opponent of strength 0 (a penalised likelihood; 0 gives the plain maximum likelihood,
/// which exists only when no group of entrants won every game against the rest). Fitted by
/// Newton's method with step halving (the likelihood never decreases) for up to
/// <see cref="NewtonLimit"/> entrants, and otherwise, or when Newton has not converged, by Hunter's
/// minorisation–maximisation iteration, which increases the likelihood at every step too.
/// </summary>
internal static class BradleyTerry
{
    /// <summary>Rating points per natural-log unit of strength: 400 points are odds of 10 to 1.</summary>
    public static readonly double PointsPerUnit = 400 / Math.Log(10);

    /// <summary>Most entrants fitted by Newton's method (each step solves a dense system of that size).</summary>
    public const int NewtonLimit = 64;

    /// <summary>Iterations before the fit gives up converging (never reached in the tests' cases).</summary>
    public const int MaximumIterations = 200_000;

    /// <summary>The strengths θ of <paramref name="entrants"/> entrants, centred to mean 0.</summary>
    /// <param name="entrants">Number of entrants, ≥ 1.</param>
    /// <param name="games">The games; entrants are 0 … entrants − 1.</param>
    /// <param name="prior">Virtual draws of each entrant against a fixed opponent of strength 0, ≥ 0.</param>
    /// <param name="start">Strengths to start from (e.g. the fit of the whole sample for a bootstrap replicate), or null for 0.</param>
    /// <param name="centre">Whether to shift the strengths to mean 0 (false: as fitted, relative to the prior's opponent at 0).</param>
    /// <exception cref="ArgumentException">A game names an entrant out of range, a score is not 0, ½ or 1, or prior is negative.</exception>
    public static double[] Fit(int entrants, IReadOnlyList<Game> games, double prior, double[]? start = null, bool centre = true)
    {
        ArgumentOutOfRangeException.ThrowIfLessThan(entrants, 1);
        if (!(prior >= 0) || double.IsInfinity(prior))
        {
            throw new ArgumentException($"prior must be a finite number >= 0, got {prior}", nameof(prior));
        }

        var wins = new double[entrants];
        var pairs = new double[entrants * entrants];
        foreach (var g in games)
        {
            if ((uint)g.A >= (uint)entrants || (uint)g.B >= (uint)entrants || g.A == g.B)
            {
                throw new ArgumentException($"game between entrants {g.A} and {g.B}: each must be 0..{entrants - 1} and they must differ", nameof(games));
            }

            if (g.ScoreA is not (0 or 0.5 or 1))
            {
                throw new ArgumentException($"game score must be 0, 0.5 or 1, got {g.ScoreA}", nameof(games));
            }

            wins[g.A] += g.ScoreA;
            wins[g.B] += 1 - g.ScoreA;
            pairs[(g.A * entrants) + g.B]++;
            pairs[(g.B * entrants) + g.A]++;
        }

        var theta = Solve(entrants, wins, pairs, prior, start);
        if (centre)
        {
            Centre(theta);
        }

        return theta;
    }

    /// <summary>Shifts <paramref name="theta"/> to mean 0.</summary>
    public static void Centre(double[] theta)
    {
        double mean = 0;
        foreach (double t in theta)
        {
            mean += t;
        }

        mean /= theta.Length;
        for (int i = 0; i < theta.Length; i++)
        {
            theta[i] -= mean;
        }
    }

    /// <summary>The fit (not centred) from sufficient statistics: each entrant's total score and the games of each pair (symmetric, row-major).</summary>
    internal static double[] Solve(int entrants, double[] wins, double[] pairs, double prior, double[]? start)
    {
        var theta = start is null ? new double[entrants] : (double[])start.Clone();
        if (entrants <= NewtonLimit && Newton(entrants, wins, pairs, prior, theta))
        {
            return theta;
        }

        return Minorise(entrants, wins, pairs, prior, theta);
    }

    // Newton steps on the (penalised) log-likelihood, halved until it does not decrease; true when converged.
    private static bool Newton(int n, double[] wins, double[] pairs, double prior, double[] theta)
    {
        var gradient = new double[n];
        var matrix = new double[n * n];
        var step = new double[n];
        var trial = new double[n];
        double current = Objective(n, wins, pairs, prior, theta);
        for (int iteration = 0; iteration < 100; iteration++)
        {
            Array.Clear(matrix);
            for (int i = 0; i < n; i++)
            {
                double s = Sigmoid(theta[i]);
                gradient[i] = wins[i] + (prior * (0.5 - s));
                matrix[(i * n) + i] = prior * s * (1 - s);
                for (int j = 0; j < n; j++)
                {
                    double count = pairs[(i * n) + j];
                    if (count > 0)
                    {
                        double p = Sigmoid(theta[i] - theta[j]);
                        gradient[i] -= count * p;
                        double w = count * p * (1 - p);
                        matrix[(i * n) + i] += w;
                        matrix[(i * n) + j] -= w;
                    }
                }

                if (prior == 0)
                {
                    for (int j = 0; j < n; j++)
                    {
                        matrix[(i * n) + j] += 1; // only differences count: J makes the system regular, the step sums to 0
                    }
                }
            }

            if (!SolveLinear(n, matrix, gradient, step))
            {
                return false;
            }

            double scale = 1;
            double value = double.NegativeInfinity;
            for (int halving = 0; halving < 40; halving++, scale /= 2)
            {
                for (int i = 0; i < n; i++)
                {
                    trial[i] = theta[i] + (scale * step[i]);
                }

                value = Objective(n, wins, pairs, prior, trial);
                if (value >= current - (1e-12 * Math.Abs(current)))
                {
                    break;
                }
            }

            double largest = 0;
            for (int i = 0; i < n; i++)
            {
                largest = Math.Max(largest, Math.Abs(trial[i] - theta[i]));
                theta[i] = trial[i];
            }

            current = value;
            if (largest < 1e-12)
            {
                return true;
            }

            if (largest > 50)
            {
                return false; // running off to infinity (no maximum without the prior)
            }
        }

        return false;
    }

    // The log-likelihood from sufficient statistics (with the prior's virtual draws).
    private static double Objective(int n, double[] wins, double[] pairs, double prior, double[] theta)
    {
        double sum = 0;
        for (int i = 0; i < n; i++)
        {
            sum += (wins[i] * theta[i]) + (prior * ((0.5 * theta[i]) - LogOnePlusExp(theta[i])));
            for (int j = i + 1; j < n; j++)
            {
                double count = pairs[(i * n) + j];
                if (count > 0)
                {
                    double high = Math.Max(theta[i], theta[j]);
                    sum -= count * (high + LogOnePlusExp(-Math.Abs(theta[i] - theta[j])));
                }
            }
        }

        return sum;
    }

    private static double LogOnePlusExp(double x) => x > 0 ? x + Math.Log(1 + Math.Exp(-x)) : Math.Log(1 + Math.Exp(x));

    private static double Sigmoid(double x) => x >= 0 ? 1 / (1 + Math.Exp(-x)) : Math.Exp(x) / (1 + Math.Exp(x));

    // Gaussian elimination with partial pivoting of a (symmetric positive definite) system; false when singular.
    private static bool SolveLinear(int n, double[] a, double[] b, double[] x)
    {
        var m = (double[])a.Clone();
        var r = (double[])b.Clone();
        for (int c = 0; c < n; c++)
        {
            int pivot = c;
            for (int k = c + 1; k < n; k++)
            {
                if (Math.Abs(m[(k * n) + c]) > Math.Abs(m[(pivot * n) + c]))
                {
                    pivot = k;
                }
            }

            if (Math.Abs(m[(pivot * n) + c]) < 1e-300)
            {
                return false;
            }

            if (pivot != c)
            {
                for (int k = 0; k < n; k++)
                {
                    (m[(c * n) + k], m[(pivot * n) + k]) = (m[(pivot * n) + k], m[(c * n) + k]);
                }

                (r[c], r[pivot]) = (r[pivot], r[c]);
            }

            for (int k = c + 1; k < n; k++)
            {
                double f = m[(k * n) + c] / m[(c * n) + c];
                if (f == 0)
                {
                    continue;
                }

                for (int j = c; j < n; j++)
                {
                    m[(k * n) + j] -= f * m[(c * n) + j];
                }

                r[k] -= f * r[c];
            }
        }

        for (int c = n - 1; c >= 0; c--)
        {
            double sum = r[c];
            for (int j = c + 1; j < n; j++)
            {
                sum -= m[(c * n) + j] * x[j];
            }

            x[c] = sum / m[(c * n) + c];
        }

        return true;
    }

    /// <summary>Hunter's MM iteration from <paramref name="start"/> (not centred); used beyond <see cref="NewtonLimit"/> entrants or when Newton does not converge.</summary>
    internal static double[] Minorise(int entrants, double[] wins, double[] pairs, double prior, double[] start)
    {
        var gamma = new double[entrants];
        for (int i = 0; i < entrants; i++)
        {
            gamma[i] = Math.Exp(start[i]);
        }

        var next = new double[entrants];
        for (int iteration = 0; iteration < MaximumIterations; iteration++)
        {
            double largest = 0;
            for (int i = 0; i < entrants; i++)
            {
                double denominator = prior / (gamma[i] + 1);
                for (int j = 0; j < entrants; j++)
                {
                    double n = pairs[(i * entrants) + j];
                    if (n > 0)
                    {
                        denominator += n / (gamma[i] + gamma[j]);
                    }
                }

                double won = wins[i] + (prior / 2);
                next[i] = denominator > 0 ? won / denominator : gamma[i];
            }

            if (prior == 0)
            {
                Normalise(next); // without the anchor only ratios count: keep the geometric mean at 1
            }

            for (int i = 0; i < entrants; i++)
            {
                largest = Math.Max(largest, Math.Abs(Math.Log(next[i] / gamma[i])));
                gamma[i] = next[i];
            }

            if (largest < 1e-11)
            {
                break;
            }
        }

        var theta = new double[entrants];
        for (int i = 0; i < entrants; i++)
        {
            theta[i] = Math.Log(gamma[i]);
        }

        return theta;
    }

    /// <summary>The log-likelihood of <paramref name="theta"/> (with the prior's virtual draws), for checking a fit.</summary>
    public static double LogLikelihood(IReadOnlyList<Game> games, double[] theta, double prior)
    {
        double sum = 0;
        foreach (var g in games)
        {
            double d = theta[g.A] - theta[g.B];
            sum += (g.ScoreA * LogSigmoid(d)) + ((1 - g.ScoreA) * LogSigmoid(-d));
        }

        foreach (double t in theta)
        {
            sum += prior * 0.5 * (LogSigmoid(t) + LogSigmoid(-t));
        }

        return sum;
    }

    private static double LogSigmoid(double x) => x >= 0 ? -Math.Log(1 + Math.Exp(-x)) : x - Math.Log(1 + Math.Exp(x));

    private static void Normalise(double[] gamma)
    {
        double logMean = 0;
        foreach (double g in gamma)
        {
            logMean += Math.Log(g);
        }

        double scale = Math.Exp(-logMean / gamma.Length);
        for (int i = 0; i < gamma.Length; i++)
        {
            gamma[i] *= scale;
        }
    }
}
