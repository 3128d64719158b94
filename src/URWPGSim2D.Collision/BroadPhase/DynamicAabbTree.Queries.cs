namespace URWPGSim2D.Collision.BroadPhase;

/// <summary>What a walk of the tree asks of each proxy it reaches (a ray's or a point's).</summary>
internal interface IProxyVisitor
{
    /// <summary>Looks at one proxy whose fat box the walk reached.</summary>
    /// <param name="proxy">The proxy.</param>
    /// <returns>The walk's bound from now on: the ray fraction, or the distance, past which nothing matters any more.</returns>
    float Visit(int proxy);
}

/// <content>
/// Walks for queries: proxies appended one at a time, every leaf a segment reaches, and the leaves
/// near a point, nearest first. They descend through fat boxes only, which hold the exact boxes, and
/// stop where a node is past the visitor's bound (a node exactly at it is still visited).
/// </content>
internal sealed partial class DynamicAabbTree
{
    /// <summary>Adds a proxy after the others (static) and inserts its leaf.</summary>
    /// <param name="box">Its box (mm).</param>
    /// <returns>The proxy's index.</returns>
    public int Append(in Aabb box)
    {
        int proxy = _store.Append(box);
        if (proxy == _leafOf.Length)
        {
            Array.Resize(ref _leafOf, _leafOf.Length * 2);
        }

        _leafOf[proxy] = NewLeaf(proxy);
        InsertLeaf(_leafOf[proxy]);
        return proxy;
    }

    /// <summary>Removes every proxy (keeps the storage).</summary>
    public void Clear() => Reset([], 0);

    /// <summary>
    /// Visits every proxy whose fat box the segment from <paramref name="from"/> to
    /// <paramref name="to"/> touches before the fraction the visitor last returned (<paramref name="bound"/> at first).
    /// </summary>
    /// <param name="from">The segment's start.</param>
    /// <param name="to">The segment's end.</param>
    /// <param name="bound">The fraction past which nothing matters at first (1: the whole segment).</param>
    /// <param name="visitor">The visitor: it returns the fraction past which nothing matters.</param>
    public void Segment<T>(Vector2 from, Vector2 to, float bound, ref T visitor)
        where T : IProxyVisitor, allows ref struct
    {
        if (_root == Null)
        {
            return;
        }

        Vector2 d = to - from;
        int top = 0;
        _stack[top++] = _root;
        while (top > 0)
        {
            ref Node node = ref _nodes[_stack[--top]];
            if (!Touches(from, d, node.Min, node.Max, bound))
            {
                continue;
            }

            if (node.IsLeaf)
            {
                bound = MathF.Min(bound, visitor.Visit(node.Proxy));
            }
            else
            {
                Push(ref top, node.Child1, node.Child2);
            }
        }
    }

    /// <summary>
    /// Visits the proxies whose fat boxes are within the distance the visitor last returned of
    /// <paramref name="point"/> (<paramref name="bound"/> at first), nearer subtrees first.
    /// </summary>
    /// <param name="point">The point.</param>
    /// <param name="bound">The distance past which nothing matters at first.</param>
    /// <param name="visitor">The visitor: it returns the distance past which nothing matters.</param>
    public void Near<T>(Vector2 point, float bound, ref T visitor)
        where T : IProxyVisitor, allows ref struct
    {
        if (_root == Null)
        {
            return;
        }

        int top = 0;
        _stack[top++] = _root;
        while (top > 0)
        {
            ref Node node = ref _nodes[_stack[--top]];
            if (Distance(point, node.Min, node.Max) > bound)
            {
                continue;
            }

            if (node.IsLeaf)
            {
                bound = MathF.Min(bound, visitor.Visit(node.Proxy));
                continue;
            }

            // The nearer child goes on top, to be walked first and tighten the bound sooner.
            int c1 = node.Child1, c2 = node.Child2;
            bool firstNearer = Distance(point, _nodes[c1].Min, _nodes[c1].Max) <= Distance(point, _nodes[c2].Min, _nodes[c2].Max);
            Push(ref top, firstNearer ? c2 : c1, firstNearer ? c1 : c2);
        }
    }

    // Pushes two nodes on the walk's stack (the second on top), growing it when needed.
    private void Push(ref int top, int first, int second)
    {
        if (top + 2 > _stack.Length)
        {
            Array.Resize(ref _stack, _stack.Length * 2);
        }

        _stack[top++] = first;
        _stack[top++] = second;
    }

    private static float Distance(Vector2 point, Vector2 min, Vector2 max) => Vector2.Distance(point, Vector2.Clamp(point, min, max));

    // Whether the segment from + t·d, 0 ≤ t ≤ bound, touches the closed box (slabs; an axis the
    // segment does not move along must hold its start).
    private static bool Touches(Vector2 from, Vector2 d, Vector2 min, Vector2 max, float bound)
    {
        float enter = 0f, leave = bound;
        return Slab(from.X, d.X, min.X, max.X, ref enter, ref leave) && Slab(from.Y, d.Y, min.Y, max.Y, ref enter, ref leave);
    }

    private static bool Slab(float start, float delta, float min, float max, ref float enter, ref float leave)
    {
        if (delta == 0f)
        {
            return start >= min && start <= max;
        }

        float t1 = (min - start) / delta, t2 = (max - start) / delta;
        enter = MathF.Max(enter, MathF.Min(t1, t2));
        leave = MathF.Min(leave, MathF.Max(t1, t2));
        return enter <= leave;
    }
}
