namespace URWPGSim2D.Collision.Motion;

/// <summary>Collects candidate pairs into a reusable list (for the passes without motion: settling and measuring).</summary>
internal sealed class PairCollector : IPairSink
{
    private PlannedPair[] _pairs = new PlannedPair[256];

    /// <summary>Number of pairs collected.</summary>
    public int Count { get; private set; }

    /// <summary>The pairs, in the order found.</summary>
    public ReadOnlySpan<PlannedPair> Pairs => _pairs.AsSpan(0, Count);

    /// <summary>Makes room for at least <paramref name="pairs"/> pairs.</summary>
    public void Reserve(int pairs)
    {
        if (_pairs.Length < pairs)
        {
            Array.Resize(ref _pairs, pairs);
        }
    }

    /// <summary>Empties the list.</summary>
    public void Clear() => Count = 0;

    /// <inheritdoc/>
    public void Add(in PlannedPair pair, float rate)
    {
        if (Count == _pairs.Length)
        {
            Array.Resize(ref _pairs, Count * 2);
        }

        _pairs[Count++] = pair;
    }
}
