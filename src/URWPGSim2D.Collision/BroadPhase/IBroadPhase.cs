namespace URWPGSim2D.Collision.BroadPhase;

/// <summary>
/// A broad phase over numbered boxes (proxies 0 … <see cref="Count"/> − 1): it finds the pairs of
/// proxies whose boxes overlap, so that only those go to an exact (narrow-phase) test. Boxes are
/// closed: touching boxes overlap. Proxies numbered <see cref="MovingCount"/> and above are
/// static: two static proxies are never reported as a pair. Every implementation reports exactly
/// the same pairs (those brute force finds), in the same order: by the smaller index, then by the
/// larger one. Once warmed up (buffers at their largest size), nothing allocates.
/// </summary>
internal interface IBroadPhase
{
    /// <summary>Number of proxies.</summary>
    int Count { get; }

    /// <summary>Proxies below this index are moving; the rest are static.</summary>
    int MovingCount { get; }

    /// <summary>Replaces every proxy: proxy i gets <c>boxes[i]</c>.</summary>
    /// <param name="boxes">One box per proxy (mm).</param>
    /// <param name="movingCount">How many of the first proxies are moving, 0 … boxes.Length.</param>
    /// <exception cref="ArgumentException"><paramref name="movingCount"/> is out of range.</exception>
    void Reset(ReadOnlySpan<Aabb> boxes, int movingCount);

    /// <summary>Gives one proxy a new box.</summary>
    /// <param name="proxy">The proxy, 0 … <see cref="Count"/> − 1.</param>
    /// <param name="box">Its new box (mm).</param>
    /// <exception cref="ArgumentException"><paramref name="proxy"/> is out of range.</exception>
    void Move(int proxy, in Aabb box);

    /// <summary>The current box of a proxy.</summary>
    /// <param name="proxy">The proxy, 0 … <see cref="Count"/> − 1.</param>
    /// <returns>The box last given by <see cref="Reset"/> or <see cref="Move"/>.</returns>
    /// <exception cref="ArgumentException"><paramref name="proxy"/> is out of range.</exception>
    Aabb Box(int proxy);

    /// <summary>
    /// Every pair (a, b), a &lt; b, not both static, whose boxes overlap, sorted by a then b.
    /// </summary>
    /// <param name="pairs">Cleared, then filled.</param>
    void FindPairs(PairList pairs);

    /// <summary>Every proxy whose box overlaps <paramref name="box"/>, in ascending order.</summary>
    /// <param name="box">The query box (mm).</param>
    /// <param name="result">Cleared, then filled.</param>
    void Query(in Aabb box, IndexList result);
}
