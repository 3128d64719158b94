namespace URWPGSim2D.Tournament;

/// <summary>A 95 % interval from bootstrap replicates: their 2.5 % and 97.5 % quantiles.</summary>
/// <param name="Low">The lower end.</param>
/// <param name="High">The upper end.</param>
public readonly record struct Interval(double Low, double High)
{
    /// <summary>Whether the two intervals share a point.</summary>
    public bool Overlaps(Interval other) => Low <= other.High && other.Low <= High;

    /// <summary>Whether <paramref name="value"/> lies in the interval (ends included).</summary>
    public bool Contains(double value) => Low <= value && value <= High;

    /// <summary>
    /// The percentile interval of <paramref name="replicates"/> (sorted in place): the values at
    /// ranks ⌊0.025·B⌋ and ⌈0.975·B⌉ − 1 of B (0-based), e.g. the 26th and 975th smallest of 1,000.
    /// </summary>
    public static Interval Percentile(double[] replicates)
    {
        if (replicates.Length == 0)
        {
            throw new ArgumentException("no bootstrap replicates", nameof(replicates));
        }

        Array.Sort(replicates);
        int b = replicates.Length;
        int low = (int)Math.Floor(0.025 * b);
        int high = Math.Max(low, (int)Math.Ceiling(0.975 * b) - 1);
        return new Interval(replicates[low], replicates[high]);
    }
}
