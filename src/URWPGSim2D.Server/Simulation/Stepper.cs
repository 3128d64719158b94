using System;
using System.Numerics;

namespace URWPGSim2D.Server.Simulation;

/// <summary>
/// Motion interpolation for one cycle (the paper's pseudo-continuous detection, done properly).
/// The cycle is cut into the sub-steps the <see cref="SweepPlanner"/> asks for (one when nothing
/// moves fast). Bodies move linearly in time (fish also turn at their angular velocity; tail joints
/// keep the cycle's pose throughout). At the first sub-step where a candidate pair overlaps, the
/// bodies involved go back to the last free state and the time of first contact is refined by
/// bisection; there the contacts are resolved (<see cref="ContactResponse"/>), and the rest of the
/// cycle is planned again with the new velocities. After
/// <see cref="PhysicsConstants.MaximumEventsPerCycle"/> events the rest of the cycle resolves
/// overlaps at sub-step ends without bisection.
/// </summary>
internal sealed class Stepper
{
    private readonly World _world;
    private readonly SweepPlanner _planner;
    private readonly ContactLog _log;
    private readonly ContactResponse _response;
    private readonly int[] _hits;
    private readonly Hit[] _hitValues;
    private readonly bool[] _fishInvolved;
    private readonly bool[] _ballInvolved;
    private int _hitCount;
    private double _baseTime;

    public Stepper(World world, ContactLog log)
    {
        _world = world;
        _log = log;
        _planner = new SweepPlanner(world);
        _response = new ContactResponse(world);
        _hits = new int[_planner.Capacity];
        _hitValues = new Hit[_planner.Capacity];
        _fishInvolved = new bool[world.Fish.Length];
        _ballInvolved = new bool[world.Balls.Length];
    }

    /// <summary>Sub-steps taken in the last cycle (bisection probes not counted).</summary>
    public int SubSteps { get; private set; }

    /// <summary>Contact events (times of first contact) in the last cycle.</summary>
    public int Events { get; private set; }

    /// <summary>Deepest overlap of any pair (walls included) at the end of the last cycle, mm.</summary>
    public float LeftoverOverlap { get; private set; }

    /// <summary>Moves every body through one cycle, resolving contacts on the way.</summary>
    public void Run()
    {
        SubSteps = 0;
        Events = 0;
        double t = 0.0;
        Commit(0.0);
        double h = 1.0 / _planner.Plan(1f);
        while (true)
        {
            double t1 = t + h;
            if (t1 > 1.0 - 1e-9)
            {
                t1 = 1.0;
            }

            MoveAll(t1);
            SubSteps++;
            float deepest = FindHits();
            if (_hitCount == 0)
            {
                Commit(t1);
                t = t1;
                if (t >= 1.0)
                {
                    LeftoverOverlap = deepest;
                    return;
                }

                continue;
            }

            double contact = t1;
            if (Events < PhysicsConstants.MaximumEventsPerCycle)
            {
                contact = FirstContact(t, t1);
                MoveAll(contact);
            }

            ResolveHits(contact);
            Events++;
            Commit(contact);
            t = contact;
            if (t >= 1.0)
            {
                break;
            }

            h = (1.0 - t) / _planner.Plan((float)(1.0 - t));
        }

        Settle();
    }

    /// <summary>
    /// Resolves overlaps left by a discontinuous change (a ball put back at its start, a fish's
    /// rejected move, the last contact of a cycle) without motion: a few passes of position correction and impulses, then measures the leftover.
    /// </summary>
    public void Settle()
    {
        Commit(_baseTime);
        for (int pass = 0; pass < 4; pass++)
        {
            _planner.Plan(0f);
            float deepest = FindHits();
            if (_hitCount == 0)
            {
                LeftoverOverlap = deepest;
                return;
            }

            ResolveHits(_baseTime);
        }

        LeftoverOverlap = MeasureOverlap();
    }

    /// <summary>Deepest overlap among all pairs the broad phase finds now (no motion), mm.</summary>
    public float MeasureOverlap()
    {
        Commit(_baseTime);
        _planner.Plan(0f);
        float deepest = 0f;
        foreach (ref readonly var pair in _planner.Pairs)
        {
            deepest = MathF.Max(deepest, PairDetector.Detect(_world, pair).Depth);
        }

        return deepest;
    }

    private float FindHits()
    {
        _hitCount = 0;
        float deepest = 0f;
        var pairs = _planner.Pairs;
        for (int k = 0; k < pairs.Length; k++)
        {
            Hit hit = PairDetector.Detect(_world, pairs[k]);
            deepest = MathF.Max(deepest, hit.Depth);
            if (hit.Depth > PhysicsConstants.ContactSlop)
            {
                _hitValues[_hitCount] = hit;
                _hits[_hitCount++] = k;
            }
        }

        return deepest;
    }

    private double FirstContact(double free, double hit)
    {
        Array.Clear(_fishInvolved);
        Array.Clear(_ballInvolved);
        float rate = 0f;
        var pairs = _planner.Pairs;
        for (int i = 0; i < _hitCount; i++)
        {
            ref readonly var p = ref pairs[_hits[i]];
            Mark(p);
            rate = MathF.Max(rate, _planner.PairRate(p));
        }

        MoveInvolved(free);
        if (AnyHitIntersects())
        {
            return free;
        }

        double lo = free;
        double hi = hit;
        Guess(ref lo, ref hi, rate);
        for (int iteration = 0; iteration < 48 && (hi - lo) * rate > PhysicsConstants.TimeOfImpactTolerance; iteration++)
        {
            double mid = 0.5 * (lo + hi);
            MoveInvolved(mid);
            if (AnyHitIntersects())
            {
                hi = mid;
            }
            else
            {
                lo = mid;
            }
        }

        return hi;
    }

    // False position before bisection: the deepest hit's depth shrinks at the pair's closing rate,
    // so it reached zero near hi − depth / rate. Probe there, and just after it, to bracket the time
    // of first contact tightly (exact for translation; bisection refines what turning leaves).
    private void Guess(ref double lo, ref double hi, float rate)
    {
        int deepest = 0;
        for (int i = 1; i < _hitCount; i++)
        {
            deepest = _hitValues[i].Depth > _hitValues[deepest].Depth ? i : deepest;
        }

        float closing = PairMotion.ClosingRate(_world, _planner.Pairs[_hits[deepest]], _hitValues[deepest]);
        if (!(closing > 0f) || rate <= 0f)
        {
            return;
        }

        double guess = hi - (_hitValues[deepest].Depth / closing);
        if (!(guess > lo && guess < hi))
        {
            return;
        }

        MoveInvolved(guess);
        if (AnyHitIntersects())
        {
            hi = guess;
            return;
        }

        lo = guess;
        double next = lo + (0.5 * PhysicsConstants.TimeOfImpactTolerance / rate);
        if (next < hi)
        {
            MoveInvolved(next);
            if (AnyHitIntersects())
            {
                hi = next;
            }
            else
            {
                lo = next;
            }
        }
    }

    private bool AnyHitIntersects()
    {
        var pairs = _planner.Pairs;
        for (int i = 0; i < _hitCount; i++)
        {
            if (PairDetector.Detect(_world, pairs[_hits[i]]).Depth > PhysicsConstants.ContactSlop)
            {
                return true;
            }
        }

        return false;
    }

    private void ResolveHits(double time)
    {
        var pairs = _planner.Pairs;
        for (int i = 0; i < _hitCount; i++)
        {
            ref readonly var pair = ref pairs[_hits[i]];
            Hit hit = PairDetector.Detect(_world, pair);
            if (hit.Depth > PhysicsConstants.ContactSlop)
            {
                ContactKind kind = _response.Apply(pair, hit);
                _log.Add(new ContactRecord(pair, hit.PartA, hit.PartB, hit.Mtv, hit.Normal, hit.Point, time), kind);
            }
        }
    }

    private void Mark(in CandidatePair p)
    {
        switch (p.Kind)
        {
            case PairKind.FishFish:
                _fishInvolved[p.A] = true;
                _fishInvolved[p.B] = true;
                break;
            case PairKind.FishBall:
                _fishInvolved[p.A] = true;
                _ballInvolved[p.B] = true;
                break;
            case PairKind.BallBall:
                _ballInvolved[p.A] = true;
                _ballInvolved[p.B] = true;
                break;
            case PairKind.FishStatic:
            case PairKind.FishWall:
                _fishInvolved[p.A] = true;
                break;
            default:
                _ballInvolved[p.A] = true;
                break;
        }
    }

    private void Commit(double time)
    {
        _baseTime = time;
        foreach (var f in _world.Fish)
        {
            f.BasePosition = f.Position;
            f.BaseHeading = f.Heading;
        }

        foreach (var b in _world.Balls)
        {
            b.BasePosition = b.Position;
        }
    }

    private void MoveAll(double time)
    {
        float span = (float)((time - _baseTime) * PhysicsConstants.CycleSeconds);
        foreach (var f in _world.Fish)
        {
            MoveFish(f, span);
        }

        foreach (var b in _world.Balls)
        {
            b.Position = b.BasePosition + ((b.Velocity + b.NoiseVelocity) * span);
        }
    }

    private void MoveInvolved(double time)
    {
        float span = (float)((time - _baseTime) * PhysicsConstants.CycleSeconds);
        var fish = _world.Fish;
        for (int i = 0; i < fish.Length; i++)
        {
            if (_fishInvolved[i])
            {
                MoveFish(fish[i], span);
            }
        }

        var balls = _world.Balls;
        for (int i = 0; i < balls.Length; i++)
        {
            if (_ballInvolved[i])
            {
                balls[i].Position = balls[i].BasePosition + ((balls[i].Velocity + balls[i].NoiseVelocity) * span);
            }
        }
    }

    private static void MoveFish(FishState f, float span)
    {
        Vector2 position = f.BasePosition + ((f.Velocity + f.NoiseVelocity) * span);
        float heading = Angles.Wrap(f.BaseHeading + ((f.AngularVelocity + f.NoiseAngularVelocity) * span));
        if (position == f.Position && heading == f.Heading)
        {
            return;
        }

        f.Position = position;
        f.Heading = heading;
        f.Invalidate();
    }
}
