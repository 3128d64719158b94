namespace URWPGSim2D.Collision.BroadPhase;

/// <summary>
/// Puts pairs found in any order into the common order (by A, then B): a counting sort by A
/// (O(pairs + proxies)), then an insertion sort of the few B's of each A. Its buffers grow only
/// when needed.
/// </summary>
internal sealed class PairSorter
{
    private ProxyPair[] _unsorted = new ProxyPair[64];
    private int[] _start = new int[17];

    /// <summary>Pairs collected so far.</summary>
    public int Count { get; private set; }

    public void Clear() => Count = 0;

    /// <summary>Makes room for <paramref name="pairs"/> pairs, so that collecting that many does not grow the buffer.</summary>
    public void Reserve(int pairs)
    {
        if (_unsorted.Length < pairs)
        {
            Array.Resize(ref _unsorted, pairs);
        }
    }

    /// <summary>Adds a pair (a &lt; b).</summary>
    public void Add(int a, int b)
    {
        if (Count == _unsorted.Length)
        {
            Array.Resize(ref _unsorted, _unsorted.Length * 2);
        }

        _unsorted[Count++] = new ProxyPair(a, b);
    }

    /// <summary>Writes the collected pairs, sorted, into <paramref name="pairs"/> (proxies are below <paramref name="proxyCount"/>).</summary>
    public void SortInto(int proxyCount, PairList pairs)
    {
        int count = Count;
        if (_start.Length < proxyCount + 1)
        {
            _start = new int[Math.Max(proxyCount + 1, _start.Length * 2)];
        }

        Array.Clear(_start, 0, proxyCount + 1);
        for (int k = 0; k < count; k++)
        {
            _start[_unsorted[k].A + 1]++;
        }

        for (int a = 0; a < proxyCount; a++)
        {
            _start[a + 1] += _start[a];
        }

        Span<ProxyPair> output = pairs.Resize(count);
        for (int k = 0; k < count; k++)
        {
            ProxyPair p = _unsorted[k];
            output[_start[p.A]++] = p;
        }

        for (int i = 1; i < count; i++)
        {
            ProxyPair v = output[i];
            int j = i - 1;
            while (j >= 0 && output[j].A == v.A && output[j].B > v.B)
            {
                output[j + 1] = output[j];
                j--;
            }

            output[j + 1] = v;
        }
    }
}
