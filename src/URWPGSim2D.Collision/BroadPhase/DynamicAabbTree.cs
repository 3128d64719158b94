namespace URWPGSim2D.Collision.BroadPhase;

/// <summary>
/// A dynamic bounding-volume tree of boxes. Each proxy is a leaf holding its box grown by a
/// margin (a "fat" box); internal nodes hold the union of their children. A moved proxy stays put
/// while its box remains inside its fat box, otherwise its leaf is removed and inserted again: the
/// new leaf goes down the tree toward the sibling that grows the total perimeter least, and the
/// path back up is rebalanced by AVL-style rotations. <see cref="Query"/> descends only into nodes
/// whose box overlaps the query (O(log n + k) for a balanced tree); <see cref="FindPairs"/> queries
/// the tree once per moving proxy. Fat boxes are only for the descent: every reported pair is
/// checked on the exact boxes.
/// </summary>
internal sealed partial class DynamicAabbTree : IBroadPhase
{
    private const int Null = -1;

    private readonly ProxyStore _store = new();
    private readonly float _marginScale;
    private readonly IndexList _scratch = new();
    private Node[] _nodes = new Node[32];
    private int _nodeCount;
    private int _free = Null;
    private int _root = Null;
    private int[] _leafOf = new int[16];
    private int[] _stack = new int[64];

    /// <summary>Creates an empty tree.</summary>
    /// <param name="marginScale">How much a leaf's box is grown on each side, as a fraction of its larger extent (≥ 0).</param>
    /// <exception cref="ArgumentException"><paramref name="marginScale"/> is negative or not finite.</exception>
    public DynamicAabbTree(float marginScale = 0.1f)
    {
        if (!float.IsFinite(marginScale) || marginScale < 0f)
        {
            throw new ArgumentException($"must be a finite number ≥ 0, got {marginScale}", nameof(marginScale));
        }

        _marginScale = marginScale;
    }

    /// <inheritdoc/>
    public int Count => _store.Count;

    /// <inheritdoc/>
    public int MovingCount => _store.MovingCount;

    /// <summary>Height of the tree (a single leaf has height 0; −1 when empty).</summary>
    public int Height => _root == Null ? -1 : _nodes[_root].Height;

    /// <inheritdoc/>
    public void Reset(ReadOnlySpan<Aabb> boxes, int movingCount)
    {
        int previous = _store.Count;
        _store.Reset(boxes, movingCount);
        int n = _store.Count;
        if (previous == n && _root != Null)
        {
            for (int p = 0; p < n; p++)
            {
                Refresh(p);
            }

            return;
        }

        if (_leafOf.Length < n)
        {
            _leafOf = new int[Math.Max(n, _leafOf.Length * 2)];
        }

        _nodeCount = 0;
        _free = Null;
        _root = Null;
        for (int p = 0; p < n; p++)
        {
            _leafOf[p] = NewLeaf(p);
            InsertLeaf(_leafOf[p]);
        }
    }

    /// <inheritdoc/>
    public void Move(int proxy, in Aabb box)
    {
        _store.Move(proxy, box);
        Refresh(proxy);
    }

    /// <inheritdoc/>
    public Aabb Box(int proxy) => _store.Box(proxy);

    /// <inheritdoc/>
    public void FindPairs(PairList pairs)
    {
        ArgumentNullException.ThrowIfNull(pairs);
        pairs.Clear();
        for (int a = 0; a < _store.MovingCount; a++)
        {
            _scratch.Clear();
            Collect(_store.Min[a], _store.Max[a], a);
            _scratch.SortFrom(0);
            foreach (int b in _scratch.Items)
            {
                pairs.Add(a, b);
            }
        }
    }

    /// <inheritdoc/>
    public void Query(in Aabb box, IndexList result)
    {
        ArgumentNullException.ThrowIfNull(result);
        result.Clear();
        _scratch.Clear();
        Collect(box.Min, box.Max, -1);
        _scratch.SortFrom(0);
        foreach (int p in _scratch.Items)
        {
            result.Add(p);
        }
    }

    // Every proxy p > after whose exact box overlaps [lo, hi].
    private void Collect(Vector2 lo, Vector2 hi, int after)
    {
        if (_root == Null)
        {
            return;
        }

        var min = _store.Min;
        var max = _store.Max;
        int top = 0;
        _stack[top++] = _root;
        while (top > 0)
        {
            ref Node node = ref _nodes[_stack[--top]];
            if (!ProxyBox.Overlap(lo, hi, node.Min, node.Max))
            {
                continue;
            }

            if (node.IsLeaf)
            {
                int p = node.Proxy;
                if (p > after && ProxyBox.Overlap(lo, hi, min[p], max[p]))
                {
                    _scratch.Add(p);
                }

                continue;
            }

            if (top + 2 > _stack.Length)
            {
                Array.Resize(ref _stack, _stack.Length * 2);
            }

            _stack[top++] = node.Child1;
            _stack[top++] = node.Child2;
        }
    }

    // Re-inserts a proxy's leaf when its exact box left the fat box.
    private void Refresh(int proxy)
    {
        int leaf = _leafOf[proxy];
        ref Node node = ref _nodes[leaf];
        Vector2 min = _store.Min[proxy], max = _store.Max[proxy];
        if (node.Min.X <= min.X && node.Min.Y <= min.Y && max.X <= node.Max.X && max.Y <= node.Max.Y)
        {
            return;
        }

        RemoveLeaf(leaf);
        Fatten(proxy, out node.Min, out node.Max);
        InsertLeaf(leaf);
    }

    private void Fatten(int proxy, out Vector2 min, out Vector2 max)
    {
        Vector2 lo = _store.Min[proxy], hi = _store.Max[proxy];
        Vector2 size = hi - lo;
        Vector2 margin = new(MathF.Max(size.X, size.Y) * _marginScale);
        min = lo - margin;
        max = hi + margin;
    }

    private int NewLeaf(int proxy)
    {
        int id = Allocate();
        ref Node node = ref _nodes[id];
        node.Child1 = Null;
        node.Child2 = Null;
        node.Height = 0;
        node.Proxy = proxy;
        Fatten(proxy, out node.Min, out node.Max);
        return id;
    }

    private int Allocate()
    {
        if (_free != Null)
        {
            int id = _free;
            _free = _nodes[id].Parent;
            _nodes[id].Parent = Null;
            return id;
        }

        if (_nodeCount == _nodes.Length)
        {
            Array.Resize(ref _nodes, _nodes.Length * 2);
        }

        _nodes[_nodeCount].Parent = Null;
        return _nodeCount++;
    }

    private void Release(int id)
    {
        _nodes[id].Parent = _free;
        _nodes[id].Height = -1;
        _free = id;
    }

    private static float Perimeter(Vector2 min, Vector2 max) => 2f * ((max.X - min.X) + (max.Y - min.Y));

    private struct Node
    {
        public Vector2 Min;
        public Vector2 Max;
        public int Parent;
        public int Child1;
        public int Child2;
        public int Height;
        public int Proxy;

        public readonly bool IsLeaf => Child1 == Null;
    }
}
