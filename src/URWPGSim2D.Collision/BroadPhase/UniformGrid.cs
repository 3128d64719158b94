namespace URWPGSim2D.Collision.BroadPhase;

/// <summary>
/// A uniform grid broad phase. The plane is cut into square cells of side <see cref="CellSize"/>,
/// at least as large as the boxes it holds; each proxy is listed once, in the cell of its box's
/// lower corner (min x, min z). A box b of extent ≤ s that overlaps a box a has its lower corner in
/// [a.min − s, a.max] on each axis, so a query reads only the cells of that range: 3 × 3 cells for
/// a box the size of a cell. <see cref="Reset"/> lays the grid over the boxes' lower corners (at
/// most about four cells per proxy) and counting-sorts the proxies by cell, so the boxes of a row
/// of cells are contiguous in memory; <see cref="FindPairs"/> walks the cells in order, which keeps
/// what it reads in cache, and sorts the pairs at the end (counting sort). Corners outside the grid
/// fall into its border cells, which keeps every answer exact. A proxy moved to another cell by
/// <see cref="Move"/> leaves the sorted arrays for a per-cell list until the next reset; boxes
/// larger than a cell (the occasional outlier: a very fast object's swept box, a long static wall)
/// are kept in a separate list and tested against the boxes of the cells they cover (against
/// everything when those are more than <see cref="MaxCellsPerQuery"/>). With objects of similar size,
/// <see cref="FindPairs"/> costs O(n + pairs) and <see cref="Move"/> O(1). A world of at most
/// <see cref="SmallWorld"/> proxies (a match's pool, with its 19 fish, balls, obstacles and goal
/// blocks, is one) is not laid out at all: every pair of boxes is tested, which costs it less than the cells would
/// (the same pairs, in the same order).
/// </summary>
internal sealed partial class UniformGrid : IBroadPhase
{
    private const int Empty = -1;
    private const int MaxCellsPerQuery = 1024;

    // Up to this many proxies every pair is tested: a match of 4 fish, 9 balls, 4 obstacles and 2
    // goal blocks (19 proxies) lays out and finds its pairs in under half a grid's time (0.44× in
    // a profile of 200,000 cycles); a crowd of about 70 costs the same either way.
    private const int SmallWorld = 48;

    private readonly ProxyStore _store = new();
    private readonly float _fixedCellSize;
    private readonly float _cellScale;
    private readonly PairSorter _sorter = new();
    private double _inverse = 1.0;
    private float _fit = 1f;
    private double _originX;
    private double _originY;
    private int _columns = 1;
    private int _rows = 1;
    private int[] _cellStart = new int[2];
    private int[] _slotProxy = new int[16];
    private Vector128<float>[] _slotBox = new Vector128<float>[16];
    private int[] _slotOf = new int[16];
    private int[] _cellOf = new int[16];
    private int[] _movedHead = [Empty];
    private int[] _movedNext = new int[16];
    private int _movedCount;
    private int _movedHeadsDirty;
    private int[] _oversize = new int[16];
    private int _oversizeCount;
    private bool _small;

    /// <summary>Creates a grid.</summary>
    /// <param name="cellSize">A fixed cell side (mm), or 0 to choose it at every <see cref="Reset"/>.</param>
    /// <param name="cellScale">
    /// When the side is chosen: this many times the largest extent (larger of width and height) of
    /// the moving boxes, outliers beyond four times the mean extent left out (they go to the
    /// oversize list), plus half a percent (a listed box is at most 99.5 % of a cell).
    /// </param>
    /// <exception cref="ArgumentException">A parameter is negative or not finite, or <paramref name="cellScale"/> is below 1.</exception>
    public UniformGrid(float cellSize = 0f, float cellScale = 1f)
    {
        if (!float.IsFinite(cellSize) || cellSize < 0f)
        {
            throw new ArgumentException($"must be a finite number ≥ 0, got {cellSize}", nameof(cellSize));
        }

        if (!float.IsFinite(cellScale) || !(cellScale >= 1f))
        {
            throw new ArgumentException($"must be a finite number ≥ 1, got {cellScale}", nameof(cellScale));
        }

        _fixedCellSize = cellSize;
        _cellScale = cellScale;
        CellSize = cellSize > 0f ? cellSize : 1f;
    }

    /// <summary>The side of a cell, mm (in a small world, the side the boxes call for before any layout; no cells are used).</summary>
    public float CellSize { get; private set; }

    /// <summary>Number of proxies larger than a cell (tested against everything); 0 in a small world.</summary>
    public int OversizeCount => _oversizeCount;

    /// <inheritdoc/>
    public int Count => _store.Count;

    /// <inheritdoc/>
    public int MovingCount => _store.MovingCount;

    /// <inheritdoc/>
    public void Reset(ReadOnlySpan<Aabb> boxes, int movingCount)
    {
        _store.Reset(boxes, movingCount);
        int n = _store.Count;
        if (_slotOf.Length < n)
        {
            int size = Math.Max(n, _slotOf.Length * 2);
            _slotProxy = new int[size];
            _slotBox = new Vector128<float>[size];
            _slotOf = new int[size];
            _cellOf = new int[size];
            _movedNext = new int[size];
            _oversize = new int[size];
        }

        CellSize = _fixedCellSize > 0f ? _fixedCellSize : ChooseCellSize();
        _small = n <= SmallWorld;
        if (_small)
        {
            // Nothing listed, moved or oversize: the cells keep their last layout until a large world needs them.
            _oversizeCount = 0;
            _movedCount = 0;
            return;
        }

        LayOut();
        SortIntoCells();
    }

    /// <inheritdoc/>
    public void Move(int proxy, in Aabb box)
    {
        _store.Move(proxy, box);
        if (_small)
        {
            return;
        }

        int cell = CellIndex(box.Min, box.Max);
        int slot = _slotOf[proxy];
        if (slot != Empty)
        {
            if (cell == _cellOf[proxy])
            {
                _slotBox[slot] = ProxyBox.Packed(box.Min, box.Max);
                return;
            }

            _slotProxy[slot] = Empty;
            _slotOf[proxy] = Empty;
        }
        else if (cell == _cellOf[proxy])
        {
            return;
        }
        else if (_cellOf[proxy] == Empty)
        {
            RemoveOversize(proxy);
        }
        else
        {
            RemoveMoved(proxy);
        }

        Place(proxy, cell);
    }

    /// <inheritdoc/>
    public Aabb Box(int proxy) => _store.Box(proxy);

    /// <inheritdoc/>
    public void FindPairs(PairList pairs)
    {
        ArgumentNullException.ThrowIfNull(pairs);
        if (_small)
        {
            _store.PairEveryTwo(pairs);
            return;
        }

        _sorter.Clear();
        _sorter.Reserve(pairs.Capacity);
        PairListedProxies();
        if (_movedCount > 0)
        {
            for (int a = 0; a < _store.Count; a++)
            {
                if (_slotOf[a] == Empty && _cellOf[a] != Empty)
                {
                    PairMoved(a);
                }
            }
        }

        for (int i = 0; i < _oversizeCount; i++)
        {
            PairOversize(_oversize[i]);
        }

        _sorter.SortInto(_store.Count, pairs);
    }

    /// <inheritdoc/>
    public void Query(in Aabb box, IndexList result)
    {
        ArgumentNullException.ThrowIfNull(result);
        result.Clear();
        Vector2 lo = box.Min, hi = box.Max;
        if (_small)
        {
            _store.AddOverlapping(lo, hi, result);
            return;
        }

        long cells = ((long)Column(hi.X) - Column(lo.X - CellSize) + 1) * ((long)Row(hi.Y) - Row(lo.Y - CellSize) + 1);
        if (cells > MaxCellsPerQuery)
        {
            _store.AddOverlapping(lo, hi, result);
            return;
        }

        int start = result.Count;
        var sink = new QuerySink(result);
        Scan(lo, hi, -1, ref sink);
        result.SortFrom(start);
    }

    // Every listed proxy p > after whose box overlaps [lo, hi]: its lower corner lies in the cells
    // of [lo − s, hi] (s plus a little against rounding), plus the oversize ones.
    private void Scan<TSink>(Vector2 lo, Vector2 hi, int after, ref TSink sink)
        where TSink : struct, ISink
    {
        int x0 = Column(lo.X - CellSize), x1 = Column(hi.X);
        int y0 = Row(lo.Y - CellSize), y1 = Row(hi.Y);
        int[] cellStart = _cellStart;
        int[] slotProxy = _slotProxy;
        Vector128<float>[] slotBox = _slotBox;
        Vector128<float> reach = ProxyBox.Reach(ProxyBox.Packed(lo, hi));
        for (int y = y0; y <= y1; y++)
        {
            int row = y * _columns;
            int end = cellStart[row + x1 + 1];
            for (int s = cellStart[row + x0]; s < end; s++)
            {
                int p = slotProxy[s];
                if (p > after && ProxyBox.Overlap(reach, slotBox[s]))
                {
                    sink.Add(p);
                }
            }
        }

        if (_movedCount > 0)
        {
            ScanMoved(lo, hi, after, x0, x1, y0, y1, ref sink);
        }

        var min = _store.Min;
        var max = _store.Max;
        for (int i = 0; i < _oversizeCount; i++)
        {
            int p = _oversize[i];
            if (p > after && ProxyBox.Overlap(lo, hi, min[p], max[p]))
            {
                sink.Add(p);
            }
        }
    }

    private void ScanMoved<TSink>(Vector2 lo, Vector2 hi, int after, int x0, int x1, int y0, int y1, ref TSink sink)
        where TSink : struct, ISink
    {
        var min = _store.Min;
        var max = _store.Max;
        for (int y = y0; y <= y1; y++)
        {
            for (int x = x0; x <= x1; x++)
            {
                for (int p = _movedHead[(y * _columns) + x]; p != Empty; p = _movedNext[p])
                {
                    if (p > after && ProxyBox.Overlap(lo, hi, min[p], max[p]))
                    {
                        sink.Add(p);
                    }
                }
            }
        }
    }

    /// <summary>Receives the proxies a scan finds (a struct, so the scan is specialised and inlined).</summary>
    private interface ISink
    {
        void Add(int proxy);
    }

    private readonly struct QuerySink(IndexList list) : ISink
    {
        public void Add(int proxy) => list.Add(proxy);
    }

}
