using URWPGSim2D.Collision.BroadPhase;

namespace URWPGSim2D.Collision.Motion;

/// <summary>
/// Finds the candidate pairs for the rest of a step. Every mover gets a travel from the time it
/// is planned to the end of the step: the most any of its points moves over a whole step (|v|·dt,
/// plus |ω|·dt times the reach of its farthest point for a turning body, plus a fish's joints'
/// swing when they turn over the step), and a swept circle: its
/// bounding circle grown by that travel. The broad phase holds the swept circles' boxes and the
/// static bodies' boxes; a pair it reports is a candidate when the swept circles (+1 mm), or the
/// swept circle and the static box, meet. A mover is also paired with the walls when its swept
/// circle leaves the pool. Each pair gets a limit, half the sum of the two bodies' thinnest
/// widths (walls none), and its relative travel. A re-planned mover is queried against the
/// others' registered swept circles, which still cover their motion to the end of the step.
/// </summary>
internal sealed class SweepPlanner
{
    private const float Margin = 1f;

    private readonly IBroadPhase _broad;
    private Body[] _movers = [];
    private Body[] _statics = [];
    private Body? _walls;
    private Aabb[] _boxes = [];
    private Sweep[] _sweep = [];
    private PairList _found = new(256);
    private IndexList _near = new(64);
    private bool _loaded; // the broad phase holds the current bodies' boxes

    public SweepPlanner(IBroadPhase broadPhase) => _broad = broadPhase;

    /// <summary>Number of movers.</summary>
    public int Movers => _movers.Length;

    /// <summary>The movers, by slot.</summary>
    public ReadOnlySpan<Body> MoverBodies => _movers;

    /// <summary>A mover's swept circle as last measured (its bounding circle grown by its travel to the end of the step).</summary>
    public Disc SweptCircle(int m) => new(_sweep[m].Center, _sweep[m].Radius);

    /// <summary>Duration of the step being planned, s.</summary>
    public float Seconds { get; set; } = 0.1f;

    /// <summary>Takes a new set of bodies (movers, static bodies, walls); allocates only here.</summary>
    public void Load(Body[] movers, Body[] statics, Body? walls)
    {
        _movers = movers;
        _statics = statics;
        _walls = walls;
        _loaded = false;
        int m = movers.Length;
        _boxes = new Aabb[m + statics.Length];
        _sweep = new Sweep[m];
        for (int s = 0; s < statics.Length; s++)
        {
            _boxes[m + s] = statics[s].Bounds;
        }

        // Room for a busy step up front (pairs of the whole world, neighbours of one body).
        _found = new PairList((8 * m) + 256);
        _near = new IndexList(256);
    }

    /// <summary>
    /// Every candidate pair for the movers at their current poses, from step time
    /// <paramref name="time"/> to the end (1: no motion left), in a fixed order: by first mover, then
    /// by partner (movers, static bodies), the walls last.
    /// </summary>
    public void PlanAll(double time, IPairSink sink)
    {
        MeasureAll(time);
        PlanMeasured(sink);
    }

    /// <summary>
    /// Every candidate pair for the movers as each was last measured (<see cref="Measure"/>, all
    /// from the same time), in the order of <see cref="PlanAll"/>.
    /// </summary>
    public void PlanMeasured(IPairSink sink)
    {
        int movers = _movers.Length;
        BuildBroadPhase();
        _broad.FindPairs(_found);
        var found = _found.Items;
        int k = 0;
        for (int m = 0; m < movers; m++)
        {
            for (; k < found.Length && found[k].A == m; k++)
            {
                TryPair(m, found[k].B, sink);
            }

            TryWall(m, sink);
        }
    }

    /// <summary>
    /// Measures the given movers again from <paramref name="time"/> (their poses or velocities
    /// changed) and reports every candidate pair they are part of. Pairs between two of them are
    /// reported once (from the one with the smaller slot).
    /// </summary>
    public void PlanFor(ReadOnlySpan<int> movers, ReadOnlySpan<bool> isListed, double time, IPairSink sink)
    {
        if (!_loaded)
        {
            // Nothing planned yet (settling before the first step).
            MeasureAll(time);
            BuildBroadPhase();
        }

        foreach (int m in movers)
        {
            Measure(m, time);
            _broad.Move(m, _boxes[m]);
        }

        foreach (int m in movers)
        {
            _broad.Query(_boxes[m], _near);
            Offer(m, _near.Items, isListed, sink);
        }
    }

    /// <summary>
    /// Mover <paramref name="m"/>'s candidate pairs among the proxies <paramref name="near"/> (in
    /// ascending order: movers by slot, then static bodies after them), then with the walls: a
    /// pair of two listed movers is reported once, from the one with the smaller slot, and a pair
    /// of two movers names the smaller slot first. <see cref="PlanFor"/> offers what the broad
    /// phase answers; the end of a step offers a mover's planned partners.
    /// </summary>
    public void Offer(int m, ReadOnlySpan<int> near, ReadOnlySpan<bool> isListed, IPairSink sink)
    {
        int count = _movers.Length;
        foreach (int b in near)
        {
            if (b == m || (b < count && isListed[b] && b < m))
            {
                continue;
            }

            if (b < count && b < m)
            {
                TryPair(b, m, sink);
            }
            else
            {
                TryPair(m, b, sink);
            }
        }

        TryWall(m, sink);
    }

    // Every mover measured from the time.
    private void MeasureAll(double time)
    {
        for (int m = 0; m < _movers.Length; m++)
        {
            Measure(m, time);
        }
    }

    // The broad phase rebuilt over the movers' boxes as last measured and the static bodies' boxes.
    private void BuildBroadPhase()
    {
        _broad.Reset(_boxes, _movers.Length);
        _loaded = true;
    }

    /// <summary>
    /// Measures mover <paramref name="m"/>'s motion from step time <paramref name="time"/> to the
    /// end of the step and its swept box (the broad phase is not told until the movers are planned).
    /// </summary>
    public void Measure(int m, double time)
    {
        float dt = Seconds;
        float remaining = (float)Math.Max(0.0, 1.0 - time);
        Body body = _movers[m];
        Disc bound = body.Bound();
        ref Sweep sweep = ref _sweep[m];
        sweep.Velocity = body.Velocity;
        if (body.Kind == BodyKind.Circle)
        {
            sweep.Spin = 0f;
        }
        else
        {
            // A fish whose joints turn over the step: its tail moves by their swing too, and reaches
            // no farther than it does now plus that swing.
            float swing = body.JointSwing;
            float reach = Vector2.Distance(bound.Center, body.Position) + bound.Radius + swing;
            sweep.Spin = (MathF.Abs(body.AngularVelocity) * reach * dt) + swing;
        }

        sweep.Rate = (sweep.Velocity.Length() * dt) + sweep.Spin;
        sweep.Thickness = body.Thickness;
        sweep.Id = body.Id;
        sweep.Collides = body.Collides;
        sweep.Center = bound.Center;
        sweep.Radius = bound.Radius + (sweep.Rate * remaining);
        Vector2 half = new(sweep.Radius + Margin);
        _boxes[m] = new Aabb(sweep.Center - half, sweep.Center + half);
    }

    // u is a mover; v a mover with v > u, or a static body (proxy ≥ movers). The swept circles are
    // tested first, from the planner's arrays: most pairs end there without reading either body.
    private void TryPair(int u, int v, IPairSink sink)
    {
        int count = _movers.Length;
        if (v >= count)
        {
            TryStatic(u, v - count, sink);
            return;
        }

        ref readonly Sweep su = ref _sweep[u];
        ref readonly Sweep sv = ref _sweep[v];
        float reach = su.Radius + sv.Radius + Margin;
        if (Vector2.DistanceSquared(su.Center, sv.Center) >= reach * reach)
        {
            return;
        }

        if (!su.Collides || !sv.Collides)
        {
            return;
        }

        float limit = 0.5f * (su.Thickness + sv.Thickness);
        float rate = ((su.Velocity - sv.Velocity).Length() * Seconds) + su.Spin + sv.Spin;
        sink.Add(new PlannedPair(su.Id, sv.Id, u, v, limit), rate);
    }

    // A static body's box is the one the broad phase holds (its bounds, never moved).
    private void TryStatic(int m, int s, IPairSink sink)
    {
        Aabb box = _boxes[_movers.Length + s];
        Vector2 c = _sweep[m].Center;
        float r = _sweep[m].Radius + Margin;
        Vector2 d = Vector2.Max(Vector2.Max(box.Min - c, c - box.Max), Vector2.Zero);
        if (d.LengthSquared() >= r * r)
        {
            return;
        }

        ref readonly Sweep sm = ref _sweep[m];
        if (!sm.Collides)
        {
            return;
        }

        Body body = _statics[s];
        float limit = 0.5f * (sm.Thickness + body.Thickness);
        sink.Add(new PlannedPair(sm.Id, body.Id, m, -1, limit), sm.Rate);
    }

    private void TryWall(int m, IPairSink sink)
    {
        if (_walls is null || !_sweep[m].Collides)
        {
            return;
        }

        Aabb pool = _walls.Bounds;
        Vector2 c = _sweep[m].Center;
        float r = _sweep[m].Radius + Margin;
        if (c.X - r > pool.Min.X && c.X + r < pool.Max.X && c.Y - r > pool.Min.Y && c.Y + r < pool.Max.Y)
        {
            return;
        }

        sink.Add(new PlannedPair(_sweep[m].Id, _walls.Id, m, -1, float.PositiveInfinity), _sweep[m].Rate);
    }

    // A mover's motion over the rest of the step, together (a pair test reads both movers' at once).
    private struct Sweep
    {
        public Vector2 Center;   // bounding circle's centre
        public float Radius;     // swept circle's radius
        public Vector2 Velocity; // mm/s
        public float Spin;       // most a point moves by turning over a whole step, mm
        public float Rate;       // most a point moves over a whole step, mm
        public float Thickness;  // the body's thinnest width, mm
        public int Id;           // the body's id
        public bool Collides;    // whether the body collides at all
    }
}
