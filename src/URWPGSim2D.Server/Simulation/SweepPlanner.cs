using System;
using System.Numerics;
using URWPGSim2D.Collision.Shapes;

namespace URWPGSim2D.Server.Simulation;

/// <summary>
/// Broad phase and sub-step sizing for the rest of a cycle. Every mover gets a travel rate (the
/// most any of its points moves per unit of cycle fraction: |v|·dt, plus |ω|·dt times the reach of
/// its farthest point for a fish). A pair is a candidate when its bounding circles, grown by that
/// travel, can meet. Each moving candidate pair may travel (relative to each other) at most half the sum of the pair's
/// thinnest widths per sub-step (a ball's diameter, a tail segment's end width, an obstacle's
/// smaller side, a goal block's depth), so neither can pass through the other between two
/// samples; walls are half-planes and never need more than one sub-step.
/// </summary>
internal sealed class SweepPlanner
{
    private const float Margin = 1f;

    private readonly World _world;
    private readonly CandidatePair[] _pairs;
    private readonly float[] _fishRate;
    private readonly float[] _ballRate;
    private readonly Vector2[] _fishVelocity;
    private readonly Vector2[] _ballVelocity;
    private readonly float[] _fishSpin;
    private readonly Circle[] _fishBound;
    private int _count;

    public SweepPlanner(World world)
    {
        _world = world;
        int f = world.Fish.Length;
        int b = world.Balls.Length;
        int s = world.Statics.Length;
        _pairs = new CandidatePair[(f * (f - 1) / 2) + (f * b) + (b * (b - 1) / 2) + ((f + b) * s) + f + b];
        _fishRate = new float[f];
        _ballRate = new float[b];
        _fishVelocity = new Vector2[f];
        _ballVelocity = new Vector2[b];
        _fishSpin = new float[f];
        _fishBound = new Circle[f];
    }

    /// <summary>Largest possible number of candidate pairs.</summary>
    public int Capacity => _pairs.Length;

    /// <summary>The candidate pairs of the last plan, in a fixed order.</summary>
    public ReadOnlySpan<CandidatePair> Pairs => _pairs.AsSpan(0, _count);

    /// <summary>Travel (mm per unit of cycle fraction) of each fish.</summary>
    public ReadOnlySpan<float> FishRate => _fishRate;

    /// <summary>Travel (mm per unit of cycle fraction) of each ball.</summary>
    public ReadOnlySpan<float> BallRate => _ballRate;

    /// <summary>
    /// Most the two bodies of a pair move relative to each other per unit of cycle fraction, mm:
    /// |vA − vB|·dt plus what each one's turning sweeps.
    /// </summary>
    public float PairRate(in CandidatePair p)
    {
        const float dt = PhysicsConstants.CycleSeconds;
        return p.Kind switch
        {
            PairKind.FishFish => ((_fishVelocity[p.A] - _fishVelocity[p.B]).Length() * dt) + _fishSpin[p.A] + _fishSpin[p.B],
            PairKind.FishBall => ((_fishVelocity[p.A] - _ballVelocity[p.B]).Length() * dt) + _fishSpin[p.A],
            PairKind.BallBall => (_ballVelocity[p.A] - _ballVelocity[p.B]).Length() * dt,
            PairKind.FishStatic or PairKind.FishWall => _fishRate[p.A],
            _ => _ballRate[p.A],
        };
    }

    /// <summary>Plans the remaining <paramref name="remaining"/> fraction of the cycle; returns the number of sub-steps.</summary>
    public int Plan(float remaining)
    {
        var world = _world;
        var fish = world.Fish;
        var balls = world.Balls;
        var statics = world.Statics;
        const float dt = PhysicsConstants.CycleSeconds;
        for (int i = 0; i < fish.Length; i++)
        {
            var f = fish[i];
            Circle bound = f.Bound();
            float reach = Vector2.Distance(bound.Center, f.Position) + bound.Radius;
            _fishVelocity[i] = f.Velocity + f.NoiseVelocity;
            _fishSpin[i] = MathF.Abs(f.AngularVelocity + f.NoiseAngularVelocity) * reach * dt;
            _fishRate[i] = (_fishVelocity[i].Length() * dt) + _fishSpin[i];
            _fishBound[i] = bound;
        }

        for (int i = 0; i < balls.Length; i++)
        {
            _ballVelocity[i] = balls[i].Velocity + balls[i].NoiseVelocity;
            _ballRate[i] = _ballVelocity[i].Length() * dt;
        }

        _count = 0;
        float worst = 0f;
        Aabb pool = world.Field.Bounds;
        for (int i = 0; i < fish.Length; i++)
        {
            Circle a = _fishBound[i];
            float ra = a.Radius + (_fishRate[i] * remaining) + Margin;
            float ta = fish[i].Thickness;
            for (int j = i + 1; j < fish.Length; j++)
            {
                Circle b = _fishBound[j];
                AddIfNear(PairKind.FishFish, i, j, a.Center, ra, b.Center, b.Radius + (_fishRate[j] * remaining), ta + fish[j].Thickness, PairRate(new CandidatePair(PairKind.FishFish, i, j, 0f)) * remaining, ref worst);
            }

            for (int j = 0; j < balls.Length; j++)
            {
                AddIfNear(PairKind.FishBall, i, j, a.Center, ra, balls[j].Position, balls[j].Radius + (_ballRate[j] * remaining), ta + (2f * balls[j].Radius), PairRate(new CandidatePair(PairKind.FishBall, i, j, 0f)) * remaining, ref worst);
            }

            AddStatics(PairKind.FishStatic, i, a.Center, ra, ta, _fishRate[i] * remaining, statics, ref worst);
            if (!Inside(pool, a.Center, ra))
            {
                _pairs[_count++] = new CandidatePair(PairKind.FishWall, i, 0, float.PositiveInfinity);
            }
        }

        for (int i = 0; i < balls.Length; i++)
        {
            float ra = balls[i].Radius + (_ballRate[i] * remaining) + Margin;
            float ta = 2f * balls[i].Radius;
            for (int j = i + 1; j < balls.Length; j++)
            {
                AddIfNear(PairKind.BallBall, i, j, balls[i].Position, ra, balls[j].Position, balls[j].Radius + (_ballRate[j] * remaining), ta + (2f * balls[j].Radius), PairRate(new CandidatePair(PairKind.BallBall, i, j, 0f)) * remaining, ref worst);
            }

            AddStatics(PairKind.BallStatic, i, balls[i].Position, ra, ta, _ballRate[i] * remaining, statics, ref worst);
            if (!Inside(pool, balls[i].Position, ra))
            {
                _pairs[_count++] = new CandidatePair(PairKind.BallWall, i, 0, float.PositiveInfinity);
            }
        }

        return (int)Math.Clamp(MathF.Ceiling(worst), 1f, PhysicsConstants.MaximumSubSteps);
    }

    private void AddIfNear(PairKind kind, int a, int b, Vector2 ca, float ra, Vector2 cb, float rb, float thicknessSum, float travel, ref float worst)
    {
        float reach = ra + rb;
        if (Vector2.DistanceSquared(ca, cb) >= reach * reach)
        {
            return;
        }

        float limit = 0.5f * thicknessSum;
        _pairs[_count++] = new CandidatePair(kind, a, b, limit);
        worst = MathF.Max(worst, travel / limit);
    }

    private void AddStatics(PairKind kind, int a, Vector2 center, float radius, float thickness, float travel, StaticBody[] statics, ref float worst)
    {
        for (int s = 0; s < statics.Length; s++)
        {
            Aabb box = statics[s].Bounds;
            Vector2 d = Vector2.Max(Vector2.Max(box.Min - center, center - box.Max), Vector2.Zero);
            if (d.LengthSquared() >= radius * radius)
            {
                continue;
            }

            float limit = 0.5f * (thickness + statics[s].Thickness);
            _pairs[_count++] = new CandidatePair(kind, a, s, limit);
            worst = MathF.Max(worst, travel / limit);
        }
    }

    private static bool Inside(in Aabb pool, Vector2 c, float r) =>
        c.X - r > pool.Min.X && c.X + r < pool.Max.X && c.Y - r > pool.Min.Y && c.Y + r < pool.Max.Y;
}
