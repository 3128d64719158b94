namespace URWPGSim2D.Collision.BroadPhase;

/// <content>Choosing the cell size, laying out the grid, sorting proxies into cells, moved and oversize proxies.</content>
internal sealed partial class UniformGrid
{
    // Largest extent of the moving boxes (all boxes when none moves), leaving out outliers beyond
    // four times the mean, times the scale.
    private float ChooseCellSize()
    {
        int count = _store.MovingCount > 0 ? _store.MovingCount : _store.Count;
        var min = _store.Min;
        var max = _store.Max;
        double sum = 0;
        for (int i = 0; i < count; i++)
        {
            Vector2 size = max[i] - min[i];
            sum += MathF.Max(size.X, size.Y);
        }

        float limit = count > 0 ? 4f * (float)(sum / count) : 0f;
        float largest = 0f;
        for (int i = 0; i < count; i++)
        {
            Vector2 size = max[i] - min[i];
            float extent = MathF.Max(size.X, size.Y);
            if (extent <= limit)
            {
                largest = MathF.Max(largest, extent);
            }
        }

        float cell = largest * _cellScale / FitFraction;
        return float.IsFinite(cell) && cell > 1e-3f ? cell : 1f;
    }

    // Sizes the grid to the lower corners of the current boxes; the cells grow when there would be
    // more than about four per proxy.
    private void LayOut()
    {
        // Only a large world is laid out: there is at least one proxy.
        Vector2 lo = new(float.PositiveInfinity), hi = new(float.NegativeInfinity);
        for (int p = 0; p < _store.Count; p++)
        {
            lo = Vector2.Min(lo, _store.Min[p]);
            hi = Vector2.Max(hi, _store.Min[p]);
        }

        long budget = (4L * _store.Count) + 64;
        while (true)
        {
            double columns = Math.Floor((hi.X - lo.X) / (double)CellSize) + 1;
            double rows = Math.Floor((hi.Y - lo.Y) / (double)CellSize) + 1;
            if (columns * rows <= budget)
            {
                _columns = (int)columns;
                _rows = (int)rows;
                break;
            }

            CellSize *= 1.5f;
        }

        _originX = lo.X;
        _originY = lo.Y;
        _inverse = 1.0 / CellSize;
        _fit = CellSize * FitFraction;
        // Room for the most cells this many proxies can have (the budget, never less than the cells),
        // so that bodies spreading out later (a larger layout, as many proxies) grow nothing.
        if (_cellStart.Length < budget + 1)
        {
            int size = (int)Math.Max(budget + 1, _cellStart.Length * 2L);
            _cellStart = new int[size];
            _movedHead = new int[size];
            _movedHeadsDirty = size;
        }
    }

    // Counting sort of the proxies by cell (ascending proxy index within a cell); oversize ones to their list.
    private void SortIntoCells()
    {
        int cells = _columns * _rows;
        int n = _store.Count;
        var min = _store.Min;
        var max = _store.Max;
        Array.Clear(_cellStart, 0, cells + 1);
        _oversizeCount = 0;
        for (int p = 0; p < n; p++)
        {
            int cell = CellIndex(min[p], max[p]);
            _cellOf[p] = cell;
            if (cell == Empty)
            {
                _oversize[_oversizeCount++] = p;
                _slotOf[p] = Empty;
            }
            else
            {
                _cellStart[cell]++;
            }
        }

        for (int c = 1; c < cells; c++)
        {
            _cellStart[c] += _cellStart[c - 1];
        }

        int listed = _cellStart[cells - 1];
        _cellStart[cells] = listed;
        for (int p = n - 1; p >= 0; p--)
        {
            int cell = _cellOf[p];
            if (cell != Empty)
            {
                int slot = --_cellStart[cell];
                _slotProxy[slot] = p;
                _slotBox[slot] = ProxyBox.Packed(min[p], max[p]);
                _slotOf[p] = slot;
            }
        }

        // Every head a move may have used since the last reset (in this or an earlier layout) is emptied.
        if (_movedHeadsDirty > 0)
        {
            _movedHead.AsSpan(0, _movedHeadsDirty).Fill(Empty);
            _movedHeadsDirty = 0;
        }

        _movedCount = 0;
    }

    private void Place(int proxy, int cell)
    {
        _cellOf[proxy] = cell;
        if (cell == Empty)
        {
            _oversize[_oversizeCount++] = proxy;
            return;
        }

        _movedNext[proxy] = _movedHead[cell];
        _movedHead[cell] = proxy;
        _movedCount++;
        _movedHeadsDirty = Math.Max(_movedHeadsDirty, _columns * _rows);
    }

    private void RemoveOversize(int proxy)
    {
        int at = Array.IndexOf(_oversize, proxy, 0, _oversizeCount);
        _oversize[at] = _oversize[--_oversizeCount];
    }

    private void RemoveMoved(int proxy)
    {
        int cell = _cellOf[proxy];
        _movedCount--;
        if (_movedHead[cell] == proxy)
        {
            _movedHead[cell] = _movedNext[proxy];
            return;
        }

        int p = _movedHead[cell];
        while (_movedNext[p] != proxy)
        {
            p = _movedNext[p];
        }

        _movedNext[p] = _movedNext[proxy];
    }

    // The cell of a box's lower corner, or Empty for a box wider or taller than FitFraction of a cell.
    private int CellIndex(Vector2 min, Vector2 max)
    {
        Vector2 size = max - min;
        if (!(size.X <= _fit && size.Y <= _fit))
        {
            return Empty;
        }

        return (Row(min.Y) * _columns) + Column(min.X);
    }

    // Cell coordinates in double precision: monotonic in x, and two corners less than FitFraction of a
    // cell apart are never two cells apart.
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    private int Column(float x) => (int)Math.Clamp((x - _originX) * _inverse, 0.0, _columns - 1);

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    private int Row(float z) => (int)Math.Clamp((z - _originY) * _inverse, 0.0, _rows - 1);
}
