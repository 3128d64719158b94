using URWPGSim2D.Collision.BroadPhase;
using URWPGSim2D.Collision.Queries;

namespace URWPGSim2D.Collision.Motion;

// Queries over the motion world's own bodies at their poses now: which body a ray enters first (or
// every body it enters), which bodies overlap a box or a shape, which body is nearest a point.
public sealed partial class MotionWorld
{
    /// <summary>
    /// The body the ray from <paramref name="from"/> to <paramref name="to"/> enters first, at the
    /// bodies' poses now (ties to the lower <see cref="BodyId.Index"/>). Every body counts, moving,
    /// static or the walls, whether it collides or not. The walls are the outside of the pool: a ray
    /// from inside the pool enters them where it leaves the pool.
    /// </summary>
    /// <param name="from">The ray's start, mm.</param>
    /// <param name="to">The ray's end, mm.</param>
    /// <returns>The body and the entry, or body −1 (see <see cref="ShapeQuery.RayCast(in Shape, Vector2, Vector2)"/> for the rules of a single body).</returns>
    /// <exception cref="ArgumentException">A coordinate is not finite.</exception>
    public BodyRayHit RayCast(Vector2 from, Vector2 to)
    {
        ShapeQuery.CheckRay(from, to);
        SyncQueryTree();
        var first = new FirstHit(this, from, to);
        if (_queryWalls >= 0)
        {
            first.Take(_bodies[_queryWalls], WallsRay(_bodies[_queryWalls].Bounds, from, to));
        }

        _queryTree.Segment(from, to, first.Bound, ref first);
        return first.Best;
    }

    /// <summary>Every body the ray enters, at the bodies' poses now, nearest first (equal fractions by <see cref="BodyId.Index"/>); the rules of <see cref="RayCast(Vector2, Vector2)"/>.</summary>
    /// <param name="from">The ray's start, mm.</param>
    /// <param name="to">The ray's end, mm.</param>
    /// <param name="hits">Receives the first hits, as many as fit.</param>
    /// <returns>The number of bodies entered (may exceed the length of <paramref name="hits"/>).</returns>
    /// <exception cref="ArgumentException">A coordinate is not finite.</exception>
    public int RayCastAll(Vector2 from, Vector2 to, Span<BodyRayHit> hits)
    {
        ShapeQuery.CheckRay(from, to);
        SyncQueryTree();
        var all = new AllHits(this, from, to, hits);
        if (_queryWalls >= 0)
        {
            all.Take(_bodies[_queryWalls], WallsRay(_bodies[_queryWalls].Bounds, from, to));
        }

        _queryTree.Segment(from, to, 1f, ref all);
        return all.Found;
    }

    /// <summary>The bodies whose interiors overlap a box at their poses now (touching does not count), by ascending <see cref="BodyId.Index"/>; the rules of <see cref="Overlap(in Shape, Span{BodyId})"/>.</summary>
    /// <param name="box">The box.</param>
    /// <param name="bodies">Receives the first ids, as many as fit.</param>
    /// <returns>The number of bodies overlapping (may exceed the length of <paramref name="bodies"/>).</returns>
    public int Overlap(in Aabb box, Span<BodyId> bodies)
    {
        Shape shape = box;
        return Overlap(shape, bodies);
    }

    /// <summary>
    /// The bodies whose interiors overlap a shape at their poses now (touching does not count), by
    /// ascending <see cref="BodyId.Index"/>: the narrow phase's answer, as
    /// <see cref="CollisionDetector"/> and <see cref="FishCollision"/> give it. Every body counts,
    /// whether it collides or not; the walls overlap a shape that reaches outside the pool.
    /// </summary>
    /// <param name="shape">The shape.</param>
    /// <param name="bodies">Receives the first ids, as many as fit.</param>
    /// <returns>The number of bodies overlapping (may exceed the length of <paramref name="bodies"/>).</returns>
    public int Overlap(in Shape shape, Span<BodyId> bodies)
    {
        Aabb box = QueryWorld.BoxOf(shape);
        var query = new QueryBody(in shape);
        SyncQueryTree();
        _queryTree.Query(box, _queryFound);
        bool walls = false;
        if (_queryWalls >= 0)
        {
            Aabb pool = _bodies[_queryWalls].Bounds;
            walls = box.Min.X < pool.Min.X || box.Min.Y < pool.Min.Y || box.Max.X > pool.Max.X || box.Max.Y > pool.Max.Y;
        }

        int found = 0;
        foreach (int i in _queryFound.Items)
        {
            if (walls && _queryWalls < i)
            {
                Found(_bodies[_queryWalls], bodies, ref found);
                walls = false;
            }

            Body b = _bodies[i];
            if (b.Kind == BodyKind.Walls)
            {
                continue;
            }

            // Touching does not count, so a body whose bounding circle is apart from the shape's box is out.
            QueryBound(b, out Vector2 center, out float radius);
            Vector2 nearest = Vector2.Clamp(center, box.Min, box.Max);
            if (Vector2.DistanceSquared(center, nearest) > radius * radius)
            {
                continue;
            }

            Shape scratch = default;
            if (QueryBody.Contact(query, QueryOf(b, ref scratch)).Intersect)
            {
                Found(b, bodies, ref found);
            }
        }

        if (walls)
        {
            Found(_bodies[_queryWalls], bodies, ref found);
        }

        return found;

        static void Found(Body b, Span<BodyId> bodies, ref int found)
        {
            if (found < bodies.Length)
            {
                bodies[found] = b.Handle;
            }

            found++;
        }
    }

    /// <summary>
    /// The body nearest a point at the bodies' poses now (0 inside it; equal distances to the lower
    /// <see cref="BodyId.Index"/>). Every body counts, whether it collides or not; the walls are at 0
    /// from a point outside the pool or on its edge, else at the distance to the nearest edge.
    /// </summary>
    /// <param name="point">The point, mm.</param>
    /// <returns>The body and the distance, or body −1 when the motion world has no body.</returns>
    /// <exception cref="ArgumentException"><paramref name="point"/> is not finite.</exception>
    public BodyDistance Nearest(Vector2 point)
    {
        Guard.Finite(point, nameof(point));
        SyncQueryTree();
        var nearest = new NearestBody(this, point);
        if (_queryWalls >= 0)
        {
            nearest.Take(_bodies[_queryWalls], WallsToPoint(_bodies[_queryWalls].Bounds, point));
        }

        _queryTree.Near(point, nearest.Distance, ref nearest);
        return nearest.Best;
    }

    // One body's ray entry: the walls in closed form, any other body through its bounding circle
    // first (a ray that starts outside it and misses it misses the body), then exactly.
    private static RayCastResult RayCast(Body b, Vector2 from, Vector2 to)
    {
        if (b.Kind == BodyKind.Walls)
        {
            return WallsRay(b.Bounds, from, to);
        }

        QueryBound(b, out Vector2 center, out float radius);
        if (Vector2.DistanceSquared(from, center) >= radius * radius && !RayCaster.Circle(center, radius, from, to, out _, out _))
        {
            return default;
        }

        Shape scratch = default;
        return ShapeQuery.RayCast(QueryOf(b, ref scratch), from, to);
    }

    // A body (not the walls) as the queries see it: a fish's model at its pose now, a polygon's
    // outline posed in place, a circle or a static shape (held in scratch).
    private static QueryBody QueryOf(Body b, ref Shape scratch)
    {
        switch (b.Kind)
        {
            case BodyKind.Fish:
                return new QueryBody(b.PosedModel);
            case BodyKind.Circle:
                scratch = new Circle(b.Position, b.Radius);
                break;
            case BodyKind.Polygon:
                b.Outline();
                scratch = new ConvexPolygon(b.WorldVertices, b.WorldNormals, new Circle(b.Position, b.Reach));
                break;
            default:
                scratch = b.Shape;
                break;
        }

        return new QueryBody(ref scratch);
    }

    // A circle holding a body (not the walls) now, grown by a margin for the round-off of posed
    // outlines, so that no body is skipped that the exact test would find.
    private static void QueryBound(Body b, out Vector2 center, out float radius)
    {
        Disc disc = b.Kind switch
        {
            BodyKind.Circle => new Disc(b.Position, b.Radius),
            BodyKind.Polygon => new Disc(b.Position, b.Reach),
            BodyKind.Fish => b.Bound(),
            _ => b.StaticDisc,
        };
        center = disc.Center;
        radius = (disc.Radius * 1.00001f) + 1e-3f + (1e-6f * MathF.Max(MathF.Abs(center.X), MathF.Abs(center.Y)));
    }

    // The walls fill everything outside the pool: a ray from inside the pool (or its edge) enters
    // them where it leaves the pool, with the normal pointing back in; a ray from outside is inside them.
    private static RayCastResult WallsRay(in Aabb pool, Vector2 from, Vector2 to)
    {
        Vector2 d = to - from;
        if (d == Vector2.Zero || from.X < pool.Min.X || from.Y < pool.Min.Y || from.X > pool.Max.X || from.Y > pool.Max.Y)
        {
            return default;
        }

        float exit = float.PositiveInfinity;
        Vector2 normal = default;
        if (d.X != 0f)
        {
            float t = ((d.X > 0f ? pool.Max.X : pool.Min.X) - from.X) / d.X;
            (exit, normal) = (t, new Vector2(d.X > 0f ? -1f : 1f, 0f));
        }

        if (d.Y != 0f)
        {
            float t = ((d.Y > 0f ? pool.Max.Y : pool.Min.Y) - from.Y) / d.Y;
            if (t < exit)
            {
                (exit, normal) = (t, new Vector2(0f, d.Y > 0f ? -1f : 1f));
            }
        }

        return exit <= 1f ? new RayCastResult(from + (exit * d), normal, exit) : default;
    }

    // The distance from a point to the walls: 0 outside the pool or on its edge, else to the nearest edge.
    private static DistanceResult WallsToPoint(in Aabb pool, Vector2 point)
    {
        float left = point.X - pool.Min.X, right = pool.Max.X - point.X, bottom = point.Y - pool.Min.Y, top = pool.Max.Y - point.Y;
        float least = MathF.Min(MathF.Min(left, right), MathF.Min(bottom, top));
        if (least <= 0f)
        {
            return new DistanceResult(0f, point, point);
        }

        Vector2 on = least == left ? new Vector2(pool.Min.X, point.Y)
            : least == right ? new Vector2(pool.Max.X, point.Y)
            : least == bottom ? new Vector2(point.X, pool.Min.Y)
            : new Vector2(point.X, pool.Max.Y);
        return new DistanceResult(least, on, point);
    }

    // The first body a ray enters: the least fraction, equal fractions to the lower number (bodies
    // come in any order). The tree's walk stops past the best so far.
    private struct FirstHit(MotionWorld world, Vector2 from, Vector2 to) : IProxyVisitor
    {
        public BodyRayHit Best;

        public readonly float Bound => Best.Body < 0 ? 1f : Best.Result.Fraction;

        public float Visit(int proxy)
        {
            Body b = world._bodies[proxy];
            if (b.Kind != BodyKind.Walls)
            {
                Take(b, RayCast(b, from, to));
            }

            return Bound;
        }

        public void Take(Body b, in RayCastResult hit)
        {
            if (hit.Hit && (Best.Body < 0 || hit.Fraction < Best.Result.Fraction || (hit.Fraction == Best.Result.Fraction && b.Id < Best.Body)))
            {
                Best = new BodyRayHit(b.Handle, hit);
            }
        }
    }

    // Every body a ray enters, inserted into the sorted prefix of the span by fraction, then by
    // number (bodies come in any order); hits past the span's end are counted, not kept.
    private ref struct AllHits(MotionWorld world, Vector2 from, Vector2 to, Span<BodyRayHit> hits) : IProxyVisitor
    {
        private readonly Span<BodyRayHit> _hits = hits;

        public int Found;

        public float Visit(int proxy)
        {
            Body b = world._bodies[proxy];
            if (b.Kind != BodyKind.Walls)
            {
                Take(b, RayCast(b, from, to));
            }

            return 1f;
        }

        public void Take(Body b, in RayCastResult hit)
        {
            if (!hit.Hit)
            {
                return;
            }

            int at = Math.Min(Found, _hits.Length);
            while (at > 0 && (_hits[at - 1].Result.Fraction > hit.Fraction || (_hits[at - 1].Result.Fraction == hit.Fraction && _hits[at - 1].Body > b.Id)))
            {
                if (at < _hits.Length)
                {
                    _hits[at] = _hits[at - 1];
                }

                at--;
            }

            if (at < _hits.Length)
            {
                _hits[at] = new BodyRayHit(b.Handle, hit);
            }

            Found++;
        }
    }

    // The nearest body: the least distance, equal distances to the lower number (bodies come in
    // any order). The tree's walk stops past the best so far.
    private struct NearestBody(MotionWorld world, Vector2 point) : IProxyVisitor
    {
        public BodyDistance Best;

        public float Distance = float.PositiveInfinity;

        public float Visit(int proxy)
        {
            Body b = world._bodies[proxy];
            if (b.Kind == BodyKind.Walls)
            {
                return Distance;
            }

            // A body farther than the best so far by its bounding circle cannot be nearer.
            QueryBound(b, out Vector2 center, out float radius);
            if (Vector2.Distance(center, point) - radius <= Distance)
            {
                Shape scratch = default;
                Take(b, ShapeQuery.ToPoint(QueryOf(b, ref scratch), point));
            }

            return Distance;
        }

        public void Take(Body b, in DistanceResult d)
        {
            if (d.Distance < Distance || (d.Distance == Distance && b.Id < Best.Body))
            {
                Distance = d.Distance;
                Best = new BodyDistance(b.Handle, d);
            }
        }
    }
}
