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
        BodyRayHit best = default;
        for (int i = 0; i < _bodies.Count; i++)
        {
            RayCastResult hit = RayCast(_bodies[i], from, to);
            if (hit.Hit && (best.Body < 0 || hit.Fraction < best.Result.Fraction))
            {
                best = new BodyRayHit(_bodies[i].Handle, hit);
            }
        }

        return best;
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
        int found = 0;
        for (int i = 0; i < _bodies.Count; i++)
        {
            RayCastResult hit = RayCast(_bodies[i], from, to);
            if (!hit.Hit)
            {
                continue;
            }

            // Insertion into the sorted prefix; hits past the span's end are counted, not kept.
            int at = Math.Min(found, hits.Length);
            while (at > 0 && hits[at - 1].Result.Fraction > hit.Fraction)
            {
                if (at < hits.Length)
                {
                    hits[at] = hits[at - 1];
                }

                at--;
            }

            if (at < hits.Length)
            {
                hits[at] = new BodyRayHit(_bodies[i].Handle, hit);
            }

            found++;
        }

        return found;
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
        int found = 0;
        for (int i = 0; i < _bodies.Count; i++)
        {
            Body b = _bodies[i];
            bool overlaps;
            if (b.Kind == BodyKind.Walls)
            {
                Aabb pool = b.Bounds;
                overlaps = box.Min.X < pool.Min.X || box.Min.Y < pool.Min.Y || box.Max.X > pool.Max.X || box.Max.Y > pool.Max.Y;
            }
            else
            {
                // Touching does not count, so a body whose bounding circle is apart from the shape's box is out.
                QueryBound(b, out Vector2 center, out float radius);
                Vector2 nearest = Vector2.Clamp(center, box.Min, box.Max);
                if (Vector2.DistanceSquared(center, nearest) > radius * radius)
                {
                    continue;
                }

                Shape scratch = default;
                overlaps = QueryBody.Contact(query, QueryOf(b, ref scratch)).Intersect;
            }

            if (overlaps)
            {
                if (found < bodies.Length)
                {
                    bodies[found] = b.Handle;
                }

                found++;
            }
        }

        return found;
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
        BodyDistance best = default;
        float bestDistance = float.PositiveInfinity;
        for (int i = 0; i < _bodies.Count; i++)
        {
            Body b = _bodies[i];
            DistanceResult d;
            if (b.Kind == BodyKind.Walls)
            {
                d = WallsToPoint(b.Bounds, point);
            }
            else
            {
                // A body farther than the best so far by its bounding circle cannot be nearer.
                QueryBound(b, out Vector2 center, out float radius);
                if (Vector2.Distance(center, point) - radius > bestDistance)
                {
                    continue;
                }

                Shape scratch = default;
                d = ShapeQuery.ToPoint(QueryOf(b, ref scratch), point);
            }

            if (d.Distance < bestDistance)
            {
                bestDistance = d.Distance;
                best = new BodyDistance(b.Handle, d);
            }
        }

        return best;
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
}
