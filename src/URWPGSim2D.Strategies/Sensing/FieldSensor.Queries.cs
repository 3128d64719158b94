using URWPGSim2D.Collision.Shapes;

namespace URWPGSim2D.Strategies;

public sealed partial class FieldSensor
{
    // Up to this many bodies of a kind, Nearest measures each instead of asking the broad phase.
    private const int BruteForceCount = 32;

    /// <summary>
    /// The body the ray from <paramref name="from"/> to <paramref name="to"/> enters first. A ray that
    /// starts inside a body does not hit that body (so a ray from a fish's head tip outward passes its
    /// own fish); a border is hit where the ray crosses it.
    /// </summary>
    /// <param name="from">The ray's start, mm.</param>
    /// <param name="to">The ray's end, mm.</param>
    /// <param name="kinds">The kinds of bodies looked at.</param>
    /// <param name="ignore">A body passed through (the strategy's own fish, the ball it pushes), or <see cref="SensedBody.None"/>.</param>
    /// <returns>The body and the entry (equal fractions: borders, obstacles, balls, fish, then the lower index), or a miss.</returns>
    /// <exception cref="InvalidOperationException">No snapshot has been observed.</exception>
    /// <exception cref="ArgumentException">A coordinate is not finite, or <paramref name="kinds"/> has undefined bits.</exception>
    public SensedHit RayCast(Vector2 from, Vector2 to, SensedKinds kinds = SensedKinds.All, SensedBody ignore = default)
    {
        Ready(kinds, from, to);
        var best = default(SensedHit);
        for (int slot = 0; slot < KindCount; slot++)
        {
            if (!Looks(kinds, slot))
            {
                continue;
            }

            var world = _worlds[slot];
            BodyRayHit hit;
            if (ignore.Kind == KindOf(slot))
            {
                hit = default;
                int n = Math.Min(world.RayCastAll(from, to, _rayHits), _rayHits.Length);
                foreach (var h in _rayHits.AsSpan(0, n))
                {
                    if (h.Body != ignore.Index)
                    {
                        hit = h;
                        break;
                    }
                }

                if (!hit.Result.Hit)
                {
                    continue;
                }
            }
            else
            {
                hit = world.RayCast(from, to);
                if (hit.Body < 0)
                {
                    continue;
                }
            }

            if (!best.Hit || hit.Result.Fraction < best.Result.Fraction)
            {
                best = new SensedHit(new SensedBody(KindOf(slot), hit.Body), hit.Result);
            }
        }

        return best;
    }

    /// <summary>Every body the ray enters, nearest first (equal fractions: borders, obstacles, balls, fish, then the lower index).</summary>
    /// <param name="from">The ray's start, mm.</param>
    /// <param name="to">The ray's end, mm.</param>
    /// <param name="hits">Receives the first entries, as many as fit.</param>
    /// <param name="kinds">The kinds of bodies looked at.</param>
    /// <returns>The number of bodies entered (may exceed the length of <paramref name="hits"/>).</returns>
    /// <exception cref="InvalidOperationException">No snapshot has been observed.</exception>
    /// <exception cref="ArgumentException">A coordinate is not finite, or <paramref name="kinds"/> has undefined bits.</exception>
    public int RayCastAll(Vector2 from, Vector2 to, Span<SensedHit> hits, SensedKinds kinds = SensedKinds.All)
    {
        Ready(kinds, from, to);
        int found = 0;
        for (int slot = 0; slot < KindCount; slot++)
        {
            if (!Looks(kinds, slot))
            {
                continue;
            }

            int n = Math.Min(_worlds[slot].RayCastAll(from, to, _rayHits), _rayHits.Length);
            foreach (var h in _rayHits.AsSpan(0, n))
            {
                // Insertion after every entry of equal or smaller fraction; entries past the span's end are counted, not kept.
                int at = Math.Min(found, hits.Length);
                while (at > 0 && hits[at - 1].Result.Fraction > h.Result.Fraction)
                {
                    if (at < hits.Length)
                    {
                        hits[at] = hits[at - 1];
                    }

                    at--;
                }

                if (at < hits.Length)
                {
                    hits[at] = new SensedHit(new SensedBody(KindOf(slot), h.Body), h.Result);
                }

                found++;
            }
        }

        return found;
    }

    /// <summary>
    /// The bodies whose interiors overlap a shape (touching does not count; a shape across a border
    /// overlaps it), by kind (borders, obstacles, balls, fish) and index. Circles and boxes convert
    /// to <see cref="Shape"/>: <c>Overlap(new Circle(point, 100f), found)</c>.
    /// </summary>
    /// <param name="shape">The shape, mm.</param>
    /// <param name="bodies">Receives the first bodies, as many as fit.</param>
    /// <param name="kinds">The kinds of bodies looked at.</param>
    /// <param name="ignore">A body left out, or <see cref="SensedBody.None"/>.</param>
    /// <returns>The number of bodies overlapping (may exceed the length of <paramref name="bodies"/>).</returns>
    /// <exception cref="InvalidOperationException">No snapshot has been observed.</exception>
    /// <exception cref="ArgumentException"><paramref name="kinds"/> has undefined bits.</exception>
    public int Overlap(in Shape shape, Span<SensedBody> bodies, SensedKinds kinds = SensedKinds.All, SensedBody ignore = default)
    {
        Ready(kinds);
        int found = 0;
        for (int slot = 0; slot < KindCount; slot++)
        {
            if (!Looks(kinds, slot))
            {
                continue;
            }

            int n = Math.Min(_worlds[slot].Overlap(shape, _indices), _indices.Length);
            var kind = KindOf(slot);
            foreach (int body in _indices.AsSpan(0, n))
            {
                if (kind == ignore.Kind && body == ignore.Index)
                {
                    continue;
                }

                if (found < bodies.Length)
                {
                    bodies[found] = new SensedBody(kind, body);
                }

                found++;
            }
        }

        return found;
    }

    /// <summary>The body nearest a point (0 inside it; equal distances: borders, obstacles, balls, fish, then the lower index).</summary>
    /// <param name="point">The point, mm.</param>
    /// <param name="kinds">The kinds of bodies looked at.</param>
    /// <param name="ignore">A body left out (the strategy's own fish), or <see cref="SensedBody.None"/>.</param>
    /// <returns>The body and the distance, or <see cref="SensedBody.None"/> (distance +∞) when no body was looked at.</returns>
    /// <exception cref="InvalidOperationException">No snapshot has been observed.</exception>
    /// <exception cref="ArgumentException"><paramref name="point"/> is not finite, or <paramref name="kinds"/> has undefined bits.</exception>
    public SensedDistance Nearest(Vector2 point, SensedKinds kinds = SensedKinds.All, SensedBody ignore = default)
    {
        Ready(kinds, point);
        var best = default(SensedDistance);
        for (int slot = 0; slot < KindCount; slot++)
        {
            if (!Looks(kinds, slot))
            {
                continue;
            }

            var world = _worlds[slot];
            var kind = KindOf(slot);
            if (ignore.Kind == kind || world.Count <= BruteForceCount)
            {
                // Every other body of the kind, one by one: cheaper than the broad phase for a handful.
                for (int body = 0; body < world.Count; body++)
                {
                    // A body whose bounding circle is no nearer than the best so far cannot be nearer.
                    if ((ignore.Kind == kind && body == ignore.Index) || (best.Body.Exists && !Within(BoundOf(kind, body), point, best.Result.Distance)))
                    {
                        continue;
                    }

                    Keep(ref best, new SensedBody(kind, body), DistanceTo(kind, body, point));
                }
            }
            else if (world.Nearest(point) is { Body: >= 0 } near)
            {
                Keep(ref best, new SensedBody(kind, near.Body), near.Result);
            }
        }

        return best;
    }

    /// <summary>How much room there is around a point: its distance to the nearest border or obstacle, mm (0 on or inside one).</summary>
    /// <param name="point">The point, mm.</param>
    /// <returns>The distance (+∞ on a field with no border, which a match never has).</returns>
    /// <exception cref="InvalidOperationException">No snapshot has been observed.</exception>
    /// <exception cref="ArgumentException"><paramref name="point"/> is not finite.</exception>
    public float Clearance(Vector2 point) => Nearest(point, SensedKinds.Static).Distance;

    /// <summary>How far apart two bodies are, with a closest point on each (and the fish parts holding them).</summary>
    /// <param name="a">The first body.</param>
    /// <param name="b">The second body.</param>
    /// <returns>The gap (0 when they touch or overlap; then both points are a point of the overlap), the points, and <see cref="DistanceResult.PartA"/> / <see cref="DistanceResult.PartB"/> for fish.</returns>
    /// <exception cref="InvalidOperationException">No snapshot has been observed.</exception>
    /// <exception cref="ArgumentException">A body is not one of the snapshot's.</exception>
    public DistanceResult Distance(SensedBody a, SensedBody b)
    {
        Check(a, nameof(a));
        Check(b, nameof(b));
        bool fishA = a.Kind == SensedKind.Fish, fishB = b.Kind == SensedKind.Fish;
        if (fishA)
        {
            return fishB
                ? ShapeQuery.Distance(_models[a.Index], _models[b.Index])
                : ShapeQuery.Distance(_models[a.Index], ShapeOf(b));
        }

        return fishB
            ? ShapeQuery.Distance(ShapeOf(a), _models[b.Index])
            : ShapeQuery.Distance(ShapeOf(a), ShapeOf(b));
    }

    /// <summary>How far a point is from a body (0 inside it).</summary>
    /// <param name="body">The body.</param>
    /// <param name="point">The point, mm.</param>
    /// <returns>The gap; <see cref="DistanceResult.PointA"/> is the body's nearest point (with the fish part in <see cref="DistanceResult.PartA"/>), <see cref="DistanceResult.PointB"/> the point.</returns>
    /// <exception cref="InvalidOperationException">No snapshot has been observed.</exception>
    /// <exception cref="ArgumentException">The body is not one of the snapshot's, or <paramref name="point"/> is not finite.</exception>
    public DistanceResult Distance(SensedBody body, Vector2 point)
    {
        Check(body, nameof(body));
        CheckFinite(point, nameof(point));
        return DistanceTo(body.Kind, body.Index, point);
    }

    private static void Keep(ref SensedDistance best, SensedBody body, in DistanceResult d)
    {
        if (!best.Body.Exists || d.Distance < best.Result.Distance)
        {
            best = new SensedDistance(body, d);
        }
    }

    // Whether the circle comes nearer the point than the distance (it may hold a nearer body then).
    private static bool Within(in Circle bound, Vector2 point, float distance)
    {
        float reach = distance + bound.Radius;
        return Vector2.DistanceSquared(bound.Center, point) < reach * reach;
    }

    private Circle BoundOf(SensedKind kind, int body) =>
        kind == SensedKind.Fish ? _models[body].Root : _bounds[Slot(kind)][body];

    private static bool Looks(SensedKinds kinds, int slot) => ((int)kinds & (1 << slot)) != 0;

    private static void CheckFinite(Vector2 v, string name)
    {
        if (!float.IsFinite(v.X) || !float.IsFinite(v.Y))
        {
            throw new ArgumentException($"must be a finite point, got ({v.X}, {v.Y})", name);
        }
    }

    private DistanceResult DistanceTo(SensedKind kind, int body, Vector2 point) => kind == SensedKind.Fish
        ? ShapeQuery.Distance(_models[body], point)
        : ShapeQuery.Distance(_shapes[Slot(kind)][body], point);

    private ref readonly Shape ShapeOf(SensedBody body) => ref _shapes[Slot(body.Kind)][body.Index];

    private void Ready(SensedKinds kinds)
    {
        if (!_observed)
        {
            throw new InvalidOperationException("no snapshot observed yet: call Observe(snapshot) first");
        }

        if ((kinds & ~SensedKinds.All) != 0)
        {
            throw new ArgumentException($"must be a combination of Walls, Obstacles, Balls and Fish, got {(int)kinds}", nameof(kinds));
        }
    }

    private void Ready(SensedKinds kinds, Vector2 point)
    {
        Ready(kinds);
        CheckFinite(point, nameof(point));
    }

    private void Ready(SensedKinds kinds, Vector2 from, Vector2 to)
    {
        Ready(kinds);
        CheckFinite(from, nameof(from));
        CheckFinite(to, nameof(to));
    }

    private void Check(SensedBody body, string name)
    {
        if (!_observed)
        {
            throw new InvalidOperationException("no snapshot observed yet: call Observe(snapshot) first");
        }

        int count = body.Kind is >= SensedKind.Wall and <= SensedKind.Fish ? _worlds[Slot(body.Kind)].Count : 0;
        if ((uint)body.Index >= (uint)count)
        {
            throw new ArgumentException($"must be a body of the snapshot observed, got {body.Kind} {body.Index}", name);
        }
    }
}
