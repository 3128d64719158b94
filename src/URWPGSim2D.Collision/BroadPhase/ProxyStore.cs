namespace URWPGSim2D.Collision.BroadPhase;

/// <summary>The proxies' boxes (as min and max corner arrays) and the argument checks every broad phase shares.</summary>
internal sealed class ProxyStore
{
    public Vector2[] Min = new Vector2[16];
    public Vector2[] Max = new Vector2[16];

    public int Count { get; private set; }

    public int MovingCount { get; private set; }

    /// <summary>Copies the boxes in, growing the arrays when needed.</summary>
    public void Reset(ReadOnlySpan<Aabb> boxes, int movingCount)
    {
        if ((uint)movingCount > (uint)boxes.Length)
        {
            throw new ArgumentException($"must be 0 … {boxes.Length} (the number of boxes), got {movingCount}", nameof(movingCount));
        }

        if (Min.Length < boxes.Length)
        {
            int size = Math.Max(boxes.Length, Min.Length * 2);
            Min = new Vector2[size];
            Max = new Vector2[size];
        }

        for (int i = 0; i < boxes.Length; i++)
        {
            Min[i] = boxes[i].Min;
            Max[i] = boxes[i].Max;
        }

        Count = boxes.Length;
        MovingCount = movingCount;
    }

    /// <summary>Every pair of a moving proxy and a later proxy whose boxes overlap, by testing every two: ascending A, then ascending B.</summary>
    public void PairEveryTwo(PairList pairs)
    {
        pairs.Clear();
        Vector2[] min = Min, max = Max;
        for (int a = 0; a < MovingCount; a++)
        {
            Vector2 lo = min[a], hi = max[a];
            for (int b = a + 1; b < Count; b++)
            {
                if (ProxyBox.Overlap(lo, hi, min[b], max[b]))
                {
                    pairs.Add(a, b);
                }
            }
        }
    }

    /// <summary>Appends every proxy whose box overlaps [<paramref name="lo"/>, <paramref name="hi"/>], by testing each, in ascending order.</summary>
    public void AddOverlapping(Vector2 lo, Vector2 hi, IndexList result)
    {
        for (int p = 0; p < Count; p++)
        {
            if (ProxyBox.Overlap(lo, hi, Min[p], Max[p]))
            {
                result.Add(p);
            }
        }
    }

    /// <summary>Adds a static proxy after the others, growing the arrays when needed.</summary>
    /// <returns>Its index.</returns>
    public int Append(in Aabb box)
    {
        if (Count == Min.Length)
        {
            Array.Resize(ref Min, Count * 2);
            Array.Resize(ref Max, Count * 2);
        }

        Min[Count] = box.Min;
        Max[Count] = box.Max;
        return Count++;
    }

    /// <summary>Stores a proxy's new box.</summary>
    public void Move(int proxy, in Aabb box)
    {
        Check(proxy, nameof(proxy));
        Min[proxy] = box.Min;
        Max[proxy] = box.Max;
    }

    public Aabb Box(int proxy)
    {
        Check(proxy, nameof(proxy));
        return new Aabb(Min[proxy], Max[proxy]);
    }

    /// <summary>Whether the pair (a, b) may be reported: not both static.</summary>
    public bool Pairable(int a, int b) => a < MovingCount || b < MovingCount;

    public void Check(int proxy, string name)
    {
        if ((uint)proxy >= (uint)Count)
        {
            throw new ArgumentException($"must be a proxy index 0 … {Count - 1}, got {proxy}", name);
        }
    }
}
