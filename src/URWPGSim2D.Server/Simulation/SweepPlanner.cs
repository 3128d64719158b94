using System;
using System.Numerics;
using URWPGSim2D.Collision.BroadPhase;
using URWPGSim2D.Collision.Shapes;

namespace URWPGSim2D.Server.Simulation;

/// <summary>
/// Finds the candidate pairs for the rest of a cycle. Every mover (fish i = mover i, ball j =
/// mover F + j) gets a travel rate from the time it is planned to the end of the cycle: the most
/// any of its points moves per unit of cycle fraction (|v|·dt, plus |ω|·dt times the reach of its
/// farthest point for a fish), and a swept circle: its bounding circle grown by that travel. The
/// broad phase (a <see cref="UniformGrid"/> by default) holds the swept circles' boxes and the static
/// bodies' boxes; a pair it reports is a candidate when the swept circles (+1 mm), or the swept
/// circle and the static box, meet. A mover is also paired with the walls when its swept circle
/// leaves the pool. Each pair gets a limit, half the sum of the two bodies' thinnest widths (a
/// ball's diameter, a tail segment's end width, an obstacle's smaller side, a goal block's
/// depth; walls none), and its relative travel rate. A re-planned mover is queried against the
/// others' registered swept circles, which still cover their motion to the end of the cycle.
/// </summary>
internal sealed class SweepPlanner
{
    private const float Margin = 1f;

    private readonly World _world;
    private readonly IBroadPhase _broad;
    private readonly int _fish;
    private readonly int _movers;
    private readonly Aabb[] _boxes;
    private readonly Vector2[] _velocity;
    private readonly float[] _spin;
    private readonly float[] _rate;
    private readonly Vector2[] _center;
    private readonly float[] _radius;
    private readonly float[] _thickness;
    private readonly PairList _found = new(256);
    private readonly IndexList _near = new(64);

    public SweepPlanner(World world, IBroadPhase broadPhase)
    {
        _world = world;
        _broad = broadPhase;
        _fish = world.Fish.Length;
        _movers = _fish + world.Balls.Length;
        _boxes = new Aabb[_movers + world.Statics.Length];
        _velocity = new Vector2[_movers];
        _spin = new float[_movers];
        _rate = new float[_movers];
        _center = new Vector2[_movers];
        _radius = new float[_movers];
        _thickness = new float[_movers];
        for (int s = 0; s < world.Statics.Length; s++)
        {
            _boxes[_movers + s] = world.Statics[s].Bounds;
        }
    }

    /// <summary>Number of movers (fish, then balls).</summary>
    public int Movers => _movers;

    /// <summary>Number of fish (movers below this are fish).</summary>
    public int FishCount => _fish;

    /// <summary>
    /// Every candidate pair for the movers at their current poses, from cycle time
    /// <paramref name="time"/> to the end (1: no motion left), in a fixed order: by first mover, then
    /// by partner (fish, balls, static bodies), the walls last.
    /// </summary>
    public void PlanAll(double time, IPairSink sink)
    {
        for (int m = 0; m < _movers; m++)
        {
            Measure(m, time);
        }

        _broad.Reset(_boxes, _movers);
        _broad.FindPairs(_found);
        var found = _found.Items;
        int k = 0;
        for (int m = 0; m < _movers; m++)
        {
            for (; k < found.Length && found[k].A == m; k++)
            {
                TryPair(m, found[k].B, sink);
            }

            TryWall(m, sink);
        }
    }

    /// <summary>
    /// Measures the given movers again from <paramref name="time"/> (their poses and velocities
    /// changed) and reports every candidate pair they are part of. Pairs between two of them are
    /// reported once (from the one with the smaller index).
    /// </summary>
    public void PlanFor(ReadOnlySpan<int> movers, ReadOnlySpan<bool> isListed, double time, IPairSink sink)
    {
        foreach (int m in movers)
        {
            Measure(m, time);
            _broad.Move(m, _boxes[m]);
        }

        foreach (int m in movers)
        {
            _broad.Query(_boxes[m], _near);
            foreach (int b in _near.Items)
            {
                if (b == m || (b < _movers && isListed[b] && b < m))
                {
                    continue;
                }

                if (b < _movers && b < m)
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
    }

    /// <summary>Relative travel rate of two movers u &lt; v (mm per unit of cycle fraction).</summary>
    public float PairRate(int u, int v) =>
        ((_velocity[u] - _velocity[v]).Length() * PhysicsConstants.CycleSeconds) + _spin[u] + _spin[v];

    // A mover's motion from `time` to the end of the cycle and its swept box.
    private void Measure(int m, double time)
    {
        const float dt = PhysicsConstants.CycleSeconds;
        float remaining = (float)Math.Max(0.0, 1.0 - time);
        if (m < _fish)
        {
            var f = _world.Fish[m];
            Circle bound = f.Bound();
            float reach = Vector2.Distance(bound.Center, f.Position) + bound.Radius;
            _velocity[m] = f.Velocity + f.NoiseVelocity;
            _spin[m] = MathF.Abs(f.AngularVelocity + f.NoiseAngularVelocity) * reach * dt;
            _rate[m] = (_velocity[m].Length() * dt) + _spin[m];
            _center[m] = bound.Center;
            _radius[m] = bound.Radius + (_rate[m] * remaining);
            _thickness[m] = f.Thickness;
        }
        else
        {
            var b = _world.Balls[m - _fish];
            _velocity[m] = b.Velocity + b.NoiseVelocity;
            _spin[m] = 0f;
            _rate[m] = _velocity[m].Length() * dt;
            _center[m] = b.Position;
            _radius[m] = b.Radius + (_rate[m] * remaining);
            _thickness[m] = 2f * b.Radius;
        }

        Vector2 half = new(_radius[m] + Margin);
        _boxes[m] = new Aabb(_center[m] - half, _center[m] + half);
    }

    // u is a mover; v a mover with v > u, or a static body (proxy ≥ movers).
    private void TryPair(int u, int v, IPairSink sink)
    {
        if (OutOfPlay(u) || (v < _movers && OutOfPlay(v)))
        {
            return;
        }

        if (v >= _movers)
        {
            TryStatic(u, v - _movers, sink);
            return;
        }

        float reach = _radius[u] + _radius[v] + Margin;
        if (Vector2.DistanceSquared(_center[u], _center[v]) >= reach * reach)
        {
            return;
        }

        float limit = 0.5f * (_thickness[u] + _thickness[v]);
        CandidatePair pair = u >= _fish
            ? new CandidatePair(PairKind.BallBall, u - _fish, v - _fish, limit)
            : v >= _fish
                ? new CandidatePair(PairKind.FishBall, u, v - _fish, limit)
                : new CandidatePair(PairKind.FishFish, u, v, limit);
        sink.Add(pair, u, v, PairRate(u, v));
    }

    private void TryStatic(int m, int s, IPairSink sink)
    {
        var body = _world.Statics[s];
        Aabb box = body.Bounds;
        Vector2 c = _center[m];
        float r = _radius[m] + Margin;
        Vector2 d = Vector2.Max(Vector2.Max(box.Min - c, c - box.Max), Vector2.Zero);
        if (d.LengthSquared() >= r * r)
        {
            return;
        }

        float limit = 0.5f * (_thickness[m] + body.Thickness);
        CandidatePair pair = m < _fish
            ? new CandidatePair(PairKind.FishStatic, m, s, limit)
            : new CandidatePair(PairKind.BallStatic, m - _fish, s, limit);
        sink.Add(pair, m, -1, _rate[m]);
    }

    // A fish or ball an item keeps out of play (parked, maybe outside the pool) meets nothing.
    private bool OutOfPlay(int m) => m < _fish ? _world.Fish[m].OutOfPlay : _world.Balls[m - _fish].OutOfPlay;

    private void TryWall(int m, IPairSink sink)
    {
        if (OutOfPlay(m))
        {
            return;
        }

        Aabb pool = _world.Field.Bounds;
        Vector2 c = _center[m];
        float r = _radius[m] + Margin;
        if (c.X - r > pool.Min.X && c.X + r < pool.Max.X && c.Y - r > pool.Min.Y && c.Y + r < pool.Max.Y)
        {
            return;
        }

        CandidatePair pair = m < _fish
            ? new CandidatePair(PairKind.FishWall, m, 0, float.PositiveInfinity)
            : new CandidatePair(PairKind.BallWall, m - _fish, 0, float.PositiveInfinity);
        sink.Add(pair, m, -1, _rate[m]);
    }
}
