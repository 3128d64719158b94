namespace URWPGSim2D.Engine.Items.Demo;

/// <summary>
/// The shortest way between two points round the obstacles of a field: a polyline through the
/// corners of the obstacles' bounding boxes grown by <see cref="Margin"/> (a visibility graph,
/// searched by Dijkstra). Built once per strategy from the field's obstacles (they never move);
/// whether a leg keeps the margin is the field's question (<see cref="ObstacleField.Free"/>, the
/// collision library's ray cast);
/// which corner sees which is worked out then, so a query only tests the segments from its two ends.
/// A query allocates nothing.
/// </summary>
internal sealed class Waypath
{
    /// <summary>Clearance kept between the way and every obstacle's bounding box, mm.</summary>
    public const float Margin = 150f;

    // Corners sit a little beyond the grown boxes so that the legs between them do not graze.
    private const float CornerOut = 10f;

    private readonly ObstacleField _field;
    private readonly Vector2[] _corners;
    private readonly bool[,] _sees;
    private readonly float[] _distance;
    private readonly int[] _previous;
    private readonly bool[] _done;

    /// <summary>The way-finder of a field's obstacles.</summary>
    public Waypath(ObstacleField field)
    {
        _field = field;
        Vector2 room = field.HalfField - new Vector2(Margin);
        var corners = new System.Collections.Generic.List<Vector2>();
        for (int i = 0; i < field.Count; i++)
        {
            for (int k = 0; k < 4; k++)
            {
                Vector2 c = field.Corner(i, Margin + CornerOut, k);
                if (MathF.Abs(c.X) <= room.X && MathF.Abs(c.Y) <= room.Y && field.FirstBlocking(c, c, Margin) < 0)
                {
                    corners.Add(c);
                }
            }
        }

        _corners = [.. corners];
        int n = _corners.Length;
        _sees = new bool[n, n];
        for (int a = 0; a < n; a++)
        {
            for (int b = a + 1; b < n; b++)
            {
                _sees[a, b] = _sees[b, a] = Free(_corners[a], _corners[b], Margin);
            }
        }

        _distance = new float[n + 1];
        _previous = new int[n + 1];
        _done = new bool[n + 1];
    }

    /// <summary>
    /// The first two points of the shortest way from <paramref name="from"/> to <paramref name="to"/>
    /// (the second is <paramref name="to"/> itself when one leg does; both are when the way is
    /// straight). Returns false, with both set to <paramref name="to"/>, when there is no way.
    /// </summary>
    public bool Next(Vector2 from, Vector2 to, out Vector2 first, out Vector2 second)
    {
        first = second = to;
        float fromMargin = EndMargin(from), toMargin = EndMargin(to);
        if (Free(from, to, MathF.Min(fromMargin, toMargin)))
        {
            return true;
        }

        // Dijkstra from `to` over the corners (index n is `from`), so each corner knows its way onward.
        int n = _corners.Length;
        for (int i = 0; i <= n; i++)
        {
            _distance[i] = float.PositiveInfinity;
            _previous[i] = -1;
            _done[i] = false;
        }

        for (int i = 0; i < n; i++)
        {
            if (Free(_corners[i], to, toMargin))
            {
                _distance[i] = Vector2.Distance(_corners[i], to);
            }
        }

        while (true)
        {
            int u = -1;
            for (int i = 0; i <= n; i++)
            {
                if (!_done[i] && (u < 0 || _distance[i] < _distance[u]))
                {
                    u = i;
                }
            }

            if (u < 0 || float.IsPositiveInfinity(_distance[u]) || u == n)
            {
                break;
            }

            _done[u] = true;
            for (int v = 0; v <= n; v++)
            {
                if (_done[v])
                {
                    continue;
                }

                bool sees = v == n ? Free(from, _corners[u], fromMargin) : _sees[u, v];
                Vector2 pv = v == n ? from : _corners[v];
                float d = _distance[u] + Vector2.Distance(pv, _corners[u]);
                if (sees && d < _distance[v])
                {
                    _distance[v] = d;
                    _previous[v] = u;
                }
            }
        }

        int next = _previous[n];
        if (next < 0)
        {
            return false;
        }

        first = _corners[next];
        second = _previous[next] >= 0 ? _corners[_previous[next]] : to;
        return true;
    }

    /// <summary>Whether the segment keeps <paramref name="margin"/> from every obstacle's bounding box.</summary>
    public bool Free(Vector2 a, Vector2 b, float margin) => _field.Free(a, b, margin);

    // The margin a leg from or to p can keep: the full margin, or less when p itself is closer to a box.
    private float EndMargin(Vector2 p)
    {
        float margin = Margin;
        for (int i = 0; i < _field.Count; i++)
        {
            margin = MathF.Min(margin, MathF.Max(0f, (_field.DistanceToBounds(i, p) * 0.7f) - 1f));
        }

        return margin;
    }
}
