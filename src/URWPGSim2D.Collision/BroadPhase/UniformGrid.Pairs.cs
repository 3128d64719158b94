namespace URWPGSim2D.Collision.BroadPhase;

/// <content>
/// Listing the pairs. Two listed boxes that overlap have lower corners less than a cell apart, so
/// their cells are the same or neighbours; each pair of neighbouring cells is visited once (a cell
/// with itself, its right neighbour and the three cells below), which reads the sorted arrays in
/// order. Moved and oversize proxies are then paired by their own scans of the cells they cover.
/// A small world is not laid out: every two of its boxes are tested.
/// </content>
internal sealed partial class UniformGrid
{
    /// <summary>Listed boxes are at most this fraction of a cell wide and tall (the rest are oversize).</summary>
    private const float FitFraction = 0.995f;

    private void PairListedProxies()
    {
        int[] cellStart = _cellStart;
        int[] proxy = _slotProxy;
        Vector128<float>[] box = _slotBox;
        int moving = _store.MovingCount;
        int columns = _columns;
        for (int y = 0; y < _rows; y++)
        {
            bool below = y + 1 < _rows;
            for (int x = 0; x < columns; x++)
            {
                int c = (y * columns) + x;
                int start = cellStart[c], end = cellStart[c + 1];
                if (start == end)
                {
                    continue;
                }

                // This cell and its right neighbour: one contiguous run of slots.
                int sameRowEnd = x + 1 < columns ? cellStart[c + 2] : end;
                int belowStart = 0, belowEnd = 0;
                if (below)
                {
                    int row = (y + 1) * columns;
                    belowStart = cellStart[row + Math.Max(x - 1, 0)];
                    belowEnd = cellStart[row + Math.Min(x + 1, columns - 1) + 1];
                }

                for (int i = start; i < end; i++)
                {
                    int a = proxy[i];
                    if (a == Empty)
                    {
                        continue;
                    }

                    Vector128<float> reach = ProxyBox.Reach(box[i]);
                    bool aMoves = a < moving;
                    for (int j = i + 1; j < sameRowEnd; j++)
                    {
                        Test(a, aMoves, reach, proxy[j], box[j], moving);
                    }

                    for (int j = belowStart; j < belowEnd; j++)
                    {
                        Test(a, aMoves, reach, proxy[j], box[j], moving);
                    }
                }
            }
        }
    }

    private void Test(int a, bool aMoves, Vector2 lo, Vector2 hi, int b, Vector2 minB, Vector2 maxB, int moving)
    {
        if (b != Empty && (aMoves || b < moving) && ProxyBox.Overlap(lo, hi, minB, maxB))
        {
            _sorter.Add(Math.Min(a, b), Math.Max(a, b));
        }
    }

    // The same test against a listed slot's packed box.
    private void Test(int a, bool aMoves, Vector128<float> reachA, int b, Vector128<float> boxB, int moving)
    {
        if (b != Empty && (aMoves || b < moving) && ProxyBox.Overlap(reachA, boxB))
        {
            _sorter.Add(Math.Min(a, b), Math.Max(a, b));
        }
    }

    // A moved proxy against every listed proxy near it and the moved ones with a larger index.
    private void PairMoved(int a)
    {
        int moving = _store.MovingCount;
        bool aMoves = a < moving;
        Vector2 lo = _store.Min[a], hi = _store.Max[a];
        int x0 = Column(lo.X - CellSize), x1 = Column(hi.X);
        int y0 = Row(lo.Y - CellSize), y1 = Row(hi.Y);
        PairInCells(a, aMoves, lo, hi, x0, x1, y0, y1, movedAbove: a);
    }

    // An oversize proxy against every proxy that is not oversize, and the oversize ones with a larger
    // index. A listed or moved box that overlaps it has its lower corner in the cells of
    // [lo − cell, hi] (the query's argument), so only those cells are read, unless they are too many.
    private void PairOversize(int a)
    {
        int moving = _store.MovingCount;
        bool aMoves = a < moving;
        var min = _store.Min;
        var max = _store.Max;
        Vector2 lo = min[a], hi = max[a];
        int x0 = Column(lo.X - CellSize), x1 = Column(hi.X);
        int y0 = Row(lo.Y - CellSize), y1 = Row(hi.Y);
        if ((long)(x1 - x0 + 1) * (y1 - y0 + 1) > MaxCellsPerQuery)
        {
            for (int b = 0; b < _store.Count; b++)
            {
                if (b != a && (_cellOf[b] != Empty || b > a))
                {
                    Test(a, aMoves, lo, hi, b, min[b], max[b], moving);
                }
            }

            return;
        }

        PairInCells(a, aMoves, lo, hi, x0, x1, y0, y1, movedAbove: -1);
        for (int i = 0; i < _oversizeCount; i++)
        {
            int b = _oversize[i];
            if (b > a)
            {
                Test(a, aMoves, lo, hi, b, min[b], max[b], moving);
            }
        }
    }

    // Proxy a (box [lo, hi]) against the listed boxes of the cells x0…x1 × y0…y1 and the moved
    // proxies of those cells with an index above movedAbove (a moved proxy's own pairs with moved
    // ones are found from the smaller index; an oversize proxy takes every moved one).
    private void PairInCells(int a, bool aMoves, Vector2 lo, Vector2 hi, int x0, int x1, int y0, int y1, int movedAbove)
    {
        int moving = _store.MovingCount;
        var min = _store.Min;
        var max = _store.Max;
        Vector128<float> reach = ProxyBox.Reach(ProxyBox.Packed(lo, hi));
        for (int y = y0; y <= y1; y++)
        {
            int row = y * _columns;
            int end = _cellStart[row + x1 + 1];
            for (int s = _cellStart[row + x0]; s < end; s++)
            {
                Test(a, aMoves, reach, _slotProxy[s], _slotBox[s], moving);
            }

            if (_movedCount > 0)
            {
                for (int x = x0; x <= x1; x++)
                {
                    for (int b = _movedHead[row + x]; b != Empty; b = _movedNext[b])
                    {
                        if (b > movedAbove)
                        {
                            Test(a, aMoves, lo, hi, b, min[b], max[b], moving);
                        }
                    }
                }
            }
        }
    }
}
