using System;
using System.Numerics;
using System.Runtime.CompilerServices;
using URWPGSim2D.Collision.Shapes;

namespace URWPGSim2D.Collision.BroadPhase;

/// <summary>
/// A uniform grid broad phase (spatial hashing). The plane is cut into square cells of side
/// <see cref="CellSize"/>; cell (i, j) holds x ∈ [i·s, (i + 1)·s), z ∈ [j·s, (j + 1)·s). Each proxy
/// is listed in every cell its box touches (a hash table of cell chains, so the world needs no
/// bounds), and two proxies are tested only when they share a cell. A pair that shares several
/// cells is reported once, from the cell holding the lower corner of the two boxes' intersection
/// (max of the two minima). A proxy touching more than <see cref="MaxCellsPerProxy"/> cells is kept in
/// a separate list and tested against everything. With objects of similar size and a cell about
/// their size, a proxy touches at most four cells and meets a handful of others, so
/// <see cref="FindPairs"/> costs O(n + pairs); <see cref="Move"/> only re-lists a proxy whose cell
/// range changed (stale entries are skipped by a generation stamp and swept out on the next
/// rebuild).
/// </summary>
public sealed class UniformGrid : IBroadPhase
{
    /// <summary>A proxy touching more cells than this is not listed in cells but tested against everything.</summary>
    public const int MaxCellsPerProxy = 64;

    private const int MaxCellsPerQuery = 256;
    private const int NoEntry = -1;

    private readonly ProxyStore _store = new();
    private readonly float _fixedCellSize;
    private readonly float _cellScale;
    private readonly IndexList _scratch = new();
    private float _inverse = 1f;
    private int[] _generation = new int[16];
    private CellRange[] _range = new CellRange[16];
    private int[] _head = new int[64];
    private int _mask = 63;
    private Entry[] _entries = new Entry[256];
    private int _entryCount;
    private int _liveEntries;
    private Entry[] _oversize = new Entry[16];
    private int _oversizeCount;

    /// <summary>Creates a grid.</summary>
    /// <param name="cellSize">A fixed cell side (mm), or 0 to choose it at every <see cref="Reset"/>.</param>
    /// <param name="cellScale">When the side is chosen: this many times the mean extent (larger of width and height) of the moving proxies.</param>
    /// <exception cref="ArgumentException">A parameter is negative or not finite, or <paramref name="cellScale"/> is 0.</exception>
    public UniformGrid(float cellSize = 0f, float cellScale = 1f)
    {
        if (!float.IsFinite(cellSize) || cellSize < 0f)
        {
            throw new ArgumentException($"must be a finite number ≥ 0, got {cellSize}", nameof(cellSize));
        }

        if (!float.IsFinite(cellScale) || !(cellScale > 0f))
        {
            throw new ArgumentException($"must be a finite number > 0, got {cellScale}", nameof(cellScale));
        }

        _fixedCellSize = cellSize;
        _cellScale = cellScale;
        CellSize = cellSize > 0f ? cellSize : 1f;
    }

    /// <summary>The side of a cell, mm.</summary>
    public float CellSize { get; private set; }

    /// <inheritdoc/>
    public int Count => _store.Count;

    /// <inheritdoc/>
    public int MovingCount => _store.MovingCount;

    /// <inheritdoc/>
    public void Reset(ReadOnlySpan<Aabb> boxes, int movingCount)
    {
        _store.Reset(boxes, movingCount);
        int n = _store.Count;
        if (_generation.Length < n)
        {
            int size = Math.Max(n, _generation.Length * 2);
            _generation = new int[size];
            _range = new CellRange[size];
        }

        CellSize = _fixedCellSize > 0f ? _fixedCellSize : ChooseCellSize();
        _inverse = 1f / CellSize;
        Rebuild(4 * n);
    }

    /// <inheritdoc/>
    public void Move(int proxy, in Aabb box)
    {
        _store.Move(proxy, box);
        CellRange range = RangeOf(box.Min, box.Max);
        ref CellRange old = ref _range[proxy];
        bool wasOversize = old.Oversize;
        if (range.Oversize ? wasOversize : (!wasOversize && range.SameCells(old)))
        {
            return;
        }

        _liveEntries -= wasOversize ? 0 : old.Cells;
        _generation[proxy]++;
        if (_entryCount + range.Cells > _entries.Length && _liveEntries + range.Cells <= _entries.Length / 2)
        {
            Rebuild(_head.Length);
            return;
        }

        Insert(proxy, range);
    }

    /// <inheritdoc/>
    public Aabb Box(int proxy) => _store.Box(proxy);

    /// <inheritdoc/>
    public void FindPairs(PairList pairs)
    {
        ArgumentNullException.ThrowIfNull(pairs);
        pairs.Clear();
        var min = _store.Min;
        var max = _store.Max;
        int n = _store.Count;
        for (int a = 0; a < _store.MovingCount; a++)
        {
            _scratch.Clear();
            Vector2 minA = min[a], maxA = max[a];
            CellRange ra = _range[a];
            if (ra.Oversize)
            {
                for (int b = a + 1; b < n; b++)
                {
                    if (ProxyBox.Overlap(minA, maxA, min[b], max[b]))
                    {
                        _scratch.Add(b);
                    }
                }
            }
            else
            {
                CollectFromCells(ra, minA, maxA, a);
                CollectOversize(minA, maxA, a);
                _scratch.SortFrom(0);
            }

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
        CellRange range = RangeOf(box.Min, box.Max);
        if (range.CellsLong > MaxCellsPerQuery)
        {
            var min = _store.Min;
            var max = _store.Max;
            for (int p = 0; p < _store.Count; p++)
            {
                if (ProxyBox.Overlap(box.Min, box.Max, min[p], max[p]))
                {
                    result.Add(p);
                }
            }

            return;
        }

        _scratch.Clear();
        CollectFromCells(range, box.Min, box.Max, -1);
        CollectOversize(box.Min, box.Max, -1);
        _scratch.SortFrom(0);
        foreach (int p in _scratch.Items)
        {
            result.Add(p);
        }
    }

    // Every listed proxy p > after whose box overlaps [lo, hi], found once: in the cell holding the
    // lower corner of the intersection, max(range.X0, p's X0), max(range.Y0, p's Y0).
    private void CollectFromCells(CellRange range, Vector2 lo, Vector2 hi, int after)
    {
        var min = _store.Min;
        var max = _store.Max;
        var entries = _entries;
        for (int y = range.Y0; y <= range.Y1; y++)
        {
            for (int x = range.X0; x <= range.X1; x++)
            {
                for (int e = _head[Hash(x, y) & _mask]; e != NoEntry; e = entries[e].Next)
                {
                    ref Entry entry = ref entries[e];
                    int p = entry.Proxy;
                    if (p <= after || entry.X != x || entry.Y != y || entry.Generation != _generation[p])
                    {
                        continue;
                    }

                    ref CellRange rp = ref _range[p];
                    if (Math.Max(range.X0, rp.X0) != x || Math.Max(range.Y0, rp.Y0) != y)
                    {
                        continue;
                    }

                    if (ProxyBox.Overlap(lo, hi, min[p], max[p]))
                    {
                        _scratch.Add(p);
                    }
                }
            }
        }
    }

    private void CollectOversize(Vector2 lo, Vector2 hi, int after)
    {
        var min = _store.Min;
        var max = _store.Max;
        for (int i = 0; i < _oversizeCount; i++)
        {
            int p = _oversize[i].Proxy;
            if (p > after && _oversize[i].Generation == _generation[p] && ProxyBox.Overlap(lo, hi, min[p], max[p]))
            {
                _scratch.Add(p);
            }
        }
    }

    private float ChooseCellSize()
    {
        int to = _store.MovingCount > 0 ? _store.MovingCount : _store.Count;
        double sum = 0;
        for (int i = 0; i < to; i++)
        {
            Vector2 size = _store.Max[i] - _store.Min[i];
            sum += MathF.Max(size.X, size.Y);
        }

        float mean = to > 0 ? (float)(sum / to) : 0f;
        float cell = mean * _cellScale;
        return float.IsFinite(cell) && cell > 1e-3f ? cell : 1f;
    }

    // Clears the table (sized for about `expectedEntries`) and lists every proxy again.
    private void Rebuild(int expectedEntries)
    {
        int size = 64;
        while (size < expectedEntries)
        {
            size *= 2;
        }

        if (_head.Length != size)
        {
            _head = new int[size];
        }

        _mask = size - 1;
        Array.Fill(_head, NoEntry);
        _entryCount = 0;
        _liveEntries = 0;
        _oversizeCount = 0;
        for (int p = 0; p < _store.Count; p++)
        {
            _generation[p] = 0;
            Insert(p, RangeOf(_store.Min[p], _store.Max[p]));
        }
    }

    private void Insert(int proxy, CellRange range)
    {
        _range[proxy] = range;
        int generation = _generation[proxy];
        if (range.Oversize)
        {
            if (_oversizeCount == _oversize.Length)
            {
                Array.Resize(ref _oversize, _oversize.Length * 2);
            }

            _oversize[_oversizeCount++] = new Entry { Proxy = proxy, Generation = generation };
            return;
        }

        if (_entryCount + range.Cells > _entries.Length)
        {
            Array.Resize(ref _entries, Math.Max(_entries.Length * 2, _entryCount + range.Cells));
        }

        _liveEntries += range.Cells;
        for (int y = range.Y0; y <= range.Y1; y++)
        {
            for (int x = range.X0; x <= range.X1; x++)
            {
                int h = Hash(x, y) & _mask;
                _entries[_entryCount] = new Entry { Proxy = proxy, Generation = generation, Next = _head[h], X = x, Y = y };
                _head[h] = _entryCount++;
            }
        }
    }

    private CellRange RangeOf(Vector2 min, Vector2 max) =>
        new(CellOf(min.X), CellOf(min.Y), CellOf(max.X), CellOf(max.Y));

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    private int CellOf(float v) => (int)MathF.Floor(Math.Clamp(v * _inverse, -1e9f, 1e9f));

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    private static int Hash(int x, int y) => (int)(((uint)x * 0x9E3779B1u) ^ ((uint)y * 0x85EBCA77u) ^ ((uint)y >> 7));

    private struct Entry
    {
        public int Proxy;
        public int Generation;
        public int Next;
        public int X;
        public int Y;
    }

    private readonly struct CellRange(int x0, int y0, int x1, int y1)
    {
        public readonly int X0 = x0;
        public readonly int Y0 = y0;
        public readonly int X1 = x1;
        public readonly int Y1 = y1;

        public long CellsLong => ((long)X1 - X0 + 1) * ((long)Y1 - Y0 + 1);

        public bool Oversize => CellsLong > MaxCellsPerProxy;

        public int Cells => (int)Math.Min(CellsLong, int.MaxValue);

        public bool SameCells(in CellRange other) => X0 == other.X0 && Y0 == other.Y0 && X1 == other.X1 && Y1 == other.Y1;
    }
}
