namespace URWPGSim2D.Engine.Simulation;

/// <summary>
/// A small deterministic generator (SplitMix64): the same seed gives the same sequence on every
/// machine and runtime version, unlike a time-seeded or framework-defined generator.
/// </summary>
internal sealed class SeededRandom(ulong seed)
{
    private ulong _state = seed;

    /// <summary>Starts the sequence of <paramref name="seed"/> again, as a generator made with it.</summary>
    public void Reseed(ulong seed) => _state = seed;

    /// <summary>The next 64 random bits.</summary>
    public ulong NextBits()
    {
        ulong z = _state += 0x9E3779B97F4A7C15UL;
        z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9UL;
        z = (z ^ (z >> 27)) * 0x94D049BB133111EBUL;
        return z ^ (z >> 31);
    }

    /// <summary>Uniform in [0, 1).</summary>
    public double NextUnit() => (NextBits() >> 11) * (1.0 / (1UL << 53));

    /// <summary>Uniform in [−1, 1).</summary>
    public float NextSigned() => (float)((2.0 * NextUnit()) - 1.0);
}
