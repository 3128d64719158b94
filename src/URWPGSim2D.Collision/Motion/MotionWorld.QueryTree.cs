using URWPGSim2D.Collision.BroadPhase;

namespace URWPGSim2D.Collision.Motion;

/// <content>
/// The queries' tree: a dynamic AABB tree with one proxy per body (proxy = the body's number),
/// a box holding the body now (a static body's bounds, a moving body's bounding circle's box, each
/// grown by a margin for round-off; the walls a point at the pool's centre, as the queries answer
/// them apart). It follows the bodies lazily, when a query comes: bodies added since are appended,
/// bodies placed or replaced since are moved, and after a step or <see cref="Settle"/> (and at
/// every query during one, when any body may be anywhere along its path) every moving body is. A
/// body that stays inside its leaf's fat box costs a comparison.
/// </content>
public sealed partial class MotionWorld
{
    private readonly DynamicAabbTree _queryTree = new();
    private readonly IndexList _queryMoved = new(64);
    private readonly IndexList _queryFound = new();
    private int _queryCount;
    private int _queryGeneration;
    private int _queryWalls = -1;
    private bool _queryMoversMoved;
    private bool _queryAllMoved;

    /// <summary>The tree of the bodies' boxes, brought up to date (tests).</summary>
    internal DynamicAabbTree QueryTree
    {
        get
        {
            SyncQueryTree();
            return _queryTree;
        }
    }

    // A body was placed or replaced: its box is taken again at the next query. A long list of them
    // (more than the bodies) becomes one pass over every body.
    private void QueryMoved(Body b)
    {
        if (_queryAllMoved || b.Id >= _queryCount)
        {
            return;
        }

        if (_queryMoved.Count >= Math.Max(32, _queryCount))
        {
            _queryAllMoved = true;
            _queryMoved.Clear();
            return;
        }

        _queryMoved.Add(b.Id);
    }

    private void SyncQueryTree()
    {
        if (_queryGeneration != _generation)
        {
            _queryTree.Clear();
            _queryCount = 0;
            _queryWalls = -1;
            _queryMoved.Clear();
            _queryAllMoved = false;
            _queryGeneration = _generation;
        }

        if (_queryAllMoved)
        {
            for (int i = 0; i < _queryCount; i++)
            {
                _queryTree.Move(i, QueryBox(_bodies[i]));
            }

            _queryAllMoved = false;
        }
        else if (_queryMoversMoved || _stepping)
        {
            if (_loaded)
            {
                foreach (Body b in _schedule.Planner.MoverBodies)
                {
                    if (b.Id < _queryCount)
                    {
                        _queryTree.Move(b.Id, QueryBox(b));
                    }
                }
            }
            else
            {
                for (int i = 0; i < _queryCount; i++)
                {
                    if (_bodies[i].IsMoving)
                    {
                        _queryTree.Move(i, QueryBox(_bodies[i]));
                    }
                }
            }
        }

        // During a step every moving body may be anywhere along its path at the next query.
        _queryMoversMoved = _stepping;

        foreach (int i in _queryMoved.Items)
        {
            _queryTree.Move(i, QueryBox(_bodies[i]));
        }

        _queryMoved.Clear();
        for (; _queryCount < _bodies.Count; _queryCount++)
        {
            Body b = _bodies[_queryCount];
            if (b.Kind == BodyKind.Walls)
            {
                _queryWalls = _queryCount;
            }

            _queryTree.Append(QueryBox(b));
        }
    }

    // The box the tree holds for a body: it must hold everything the exact tests can find of the
    // body, and the circle the queries check before them (so that the tree rules out no body the
    // scan of every body would have tested).
    private static Aabb QueryBox(Body b)
    {
        if (b.Kind == BodyKind.Walls)
        {
            Vector2 centre = b.Bounds.Center;
            return Aabb.Trusted(centre, centre);
        }

        Vector2 lo, hi;
        if (b.Kind == BodyKind.Static)
        {
            (lo, hi) = (b.Bounds.Min, b.Bounds.Max);
        }
        else
        {
            QueryBound(b, out Vector2 center, out float radius);
            (lo, hi) = (center - new Vector2(radius), center + new Vector2(radius));
        }

        var margin = new Vector2(1e-3f + (1e-4f * MathF.Max(hi.X - lo.X, hi.Y - lo.Y)) + (1e-6f * MathF.Max(MathF.Max(MathF.Abs(lo.X), MathF.Abs(lo.Y)), MathF.Max(MathF.Abs(hi.X), MathF.Abs(hi.Y)))));
        return Aabb.Trusted(lo - margin, hi + margin);
    }
}
