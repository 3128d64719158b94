using System;

namespace URWPGSim2D.Server.Simulation;

/// <content>Time of first contact, bodies and their clocks, the bounding-circle pre-test.</content>
internal sealed partial class Stepper
{
    // Bisection between the last time all hits were apart and the sample that found them (checked
    // first unless the hits are known to be apart then).
    private double FirstContact(double free, double hit, bool knownApart)
    {
        float rate = 0f;
        for (int i = 0; i < _hitCount; i++)
        {
            rate = MathF.Max(rate, _table.Rate[_hitSlots[i]]);
        }

        if (!knownApart)
        {
            MoveInvolved(free);
            if (AnyHitIntersects())
            {
                return free;
            }
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

        float closing = PairMotion.ClosingRate(_world, _table.Pair[_hitSlots[deepest]], _hitValues[deepest]);
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
        for (int i = 0; i < _hitCount; i++)
        {
            if (Detect(_table.Pair[_hitSlots[i]]).Depth > PhysicsConstants.ContactSlop)
            {
                return true;
            }
        }

        return false;
    }

    // The exact test, skipped (no model rebuild) when the bounding circles are apart.
    private Hit Detect(in CandidatePair pair) => PairGap.LowerBound(_world, pair) > 0f ? default : PairDetector.Detect(_world, pair);

    private void MarkInvolved(in CandidatePair p) => MarkInto(_involved, p);

    private void MoveBodies(in CandidatePair p, double time)
    {
        int fish = _planner.FishCount;
        switch (p.Kind)
        {
            case PairKind.FishFish:
                MoveTo(p.A, time);
                MoveTo(p.B, time);
                break;
            case PairKind.FishBall:
                MoveTo(p.A, time);
                MoveTo(fish + p.B, time);
                break;
            case PairKind.BallBall:
                MoveTo(fish + p.A, time);
                MoveTo(fish + p.B, time);
                break;
            case PairKind.FishStatic:
            case PairKind.FishWall:
                MoveTo(p.A, time);
                break;
            default:
                MoveTo(fish + p.A, time);
                break;
        }
    }

    private void MoveInvolved(double time)
    {
        foreach (int m in _involved.Items)
        {
            MoveTo(m, time);
        }
    }

    private void MoveTo(int mover, double time)
    {
        int fish = _planner.FishCount;
        if (mover < fish)
        {
            Motion.MoveTo(_world.Fish[mover], time);
        }
        else
        {
            Motion.MoveTo(_world.Balls[mover - fish], time);
        }
    }

    private void Rebase(int mover, double time)
    {
        int fish = _planner.FishCount;
        if (mover < fish)
        {
            Motion.Rebase(_world.Fish[mover], time);
        }
        else
        {
            Motion.Rebase(_world.Balls[mover - fish], time);
        }
    }

    private double BaseTime(int mover)
    {
        int fish = _planner.FishCount;
        return mover < fish ? _world.Fish[mover].BaseTime : _world.Balls[mover - fish].BaseTime;
    }
}
