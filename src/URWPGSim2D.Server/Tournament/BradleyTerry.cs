using System;
using System.Collections.Generic;

namespace URWPGSim2D.Server.Tournament;

/// <summary>
/// The Bradley–Terry model of two-team games, fitted by maximum likelihood: entrant i has a
/// strength θᵢ and beats j with probability 1 / (1 + e^(θⱼ − θᵢ)). A draw counts as half a win
/// and half a loss (its likelihood is p^½ (1 − p)^½). So that an entrant who won or lost every
/// game still gets a finite strength, each entrant may be given <c>prior</c> virtual draws against
/// a fixed opponent of strength 0 (a penalised likelihood; 0 gives the plain maximum likelihood,
/// which exists only when no group of entrants won every game against the rest). Fitted by
/// Hunter's minorisation–maximisation iteration, which increases the likelihood at every step.
/// </summary>
internal static class BradleyTerry
{
    /// <summary>Rating points per natural-log unit of strength: 400 points are odds of 10 to 1.</summary>
    public static readonly double PointsPerUnit = 400 / Math.Log(10);

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
        var gamma = new double[entrants];
        for (int i = 0; i < entrants; i++)
        {
            gamma[i] = start is null ? 1 : Math.Exp(start[i]);
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
