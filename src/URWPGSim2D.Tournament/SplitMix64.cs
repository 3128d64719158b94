namespace URWPGSim2D.Tournament;

/// <summary>
/// SplitMix64, a small pseudo-random generator written out here so that a seed gives the same
/// numbers on every runtime and machine (the bootstrap's intervals are part of the standings' bytes).
/// </summary>
/// <param name="seed">The seed.</param>
internal struct SplitMix64(ulong seed)
{
    private ulong _state = seed;

    /// <summary>The next 64 random bits.</summary>
    public ulong Next()
    {
        ulong z = _state += 0x9E3779B97F4A7C15UL;
        z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9UL;
        z = (z ^ (z >> 27)) * 0x94D049BB133111EBUL;
        return z ^ (z >> 31);
    }

    /// <summary>A uniform integer 0 … <paramref name="count"/> − 1 (Lemire's multiply-shift; bias below 2⁻³² for the counts used here).</summary>
    public int Below(int count) => (int)(((Next() >> 32) * (ulong)(uint)count) >> 32);

    /// <summary>A uniform double in [0, 1).</summary>
    public double NextDouble() => (Next() >> 11) * (1.0 / (1UL << 53));
}
