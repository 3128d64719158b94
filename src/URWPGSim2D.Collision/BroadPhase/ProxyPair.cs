namespace URWPGSim2D.Collision.BroadPhase;

/// <summary>
/// Two proxies of a broad phase whose boxes overlap, with <see cref="A"/> &lt; <see cref="B"/>.
/// Pairs are ordered by A, then by B (<see cref="CompareTo"/>), which is the order every broad
/// phase reports them in, whatever its algorithm.
/// </summary>
/// <param name="A">The smaller proxy index.</param>
/// <param name="B">The larger proxy index.</param>
internal readonly record struct ProxyPair(int A, int B) : System.IComparable<ProxyPair>
{
    /// <summary>Orders by <see cref="A"/>, then <see cref="B"/>.</summary>
    /// <param name="other">The pair to compare with.</param>
    /// <returns>Negative, zero or positive as this pair sorts before, with or after <paramref name="other"/>.</returns>
    public int CompareTo(ProxyPair other) => A != other.A ? A.CompareTo(other.A) : B.CompareTo(other.B);
}
