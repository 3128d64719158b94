using System.Collections.Generic;

namespace URWPGSim2D.Collision.Motion;

/// <summary>
/// The time of first contact of an event (the one time-of-impact search of the library; the
/// pair-level <see cref="TimeOfImpact"/> runs it on a world of two bodies): between the last time
/// all the event's pairs were apart and the sample that found them overlapping, a false-position
/// guess from the deepest hit's closing rate, then bisection until nothing involved moves more
/// than <see cref="MotionTolerances.TimeOfImpactTolerance"/> inside the bracket. The event's hits
/// and bodies are the ones the contact events give it (<paramref name="hits"/>, and the bodies
/// <see cref="Search"/> is given). Holds no state of its own between calls.
/// </summary>
internal sealed class FirstContactSearch(PairSchedule schedule, List<Body> bodies, EventHits hits)
{
    // Rounds of the false-position estimate of the time of first contact before bisection takes over.
    private const int GuessRounds = 3;

    private readonly PairTable _table = schedule.Table;
    private readonly PairSampler _sampler = schedule.Sampler;

    /// <summary>False-position estimate of a hit's time of first contact (its last free time when unknown).</summary>
    public double Estimate(int slot, in Hit hit, double found)
    {
        float closing = ClosingRate(_table.Pair(slot), hit);
        double guess = closing > 0f ? found - (hit.Depth / closing) : _table.LastFree(slot);
        return Math.Clamp(guess, _table.LastFree(slot), found);
    }

    /// <summary>
    /// The time of first contact of the event's hits, whose moving bodies are
    /// <paramref name="involved"/>: between the last time all hits were apart,
    /// <paramref name="free"/>, and the sample that found them, <paramref name="hit"/> (checked
    /// first unless the hits are known to be apart then), a false-position guess, then bisection
    /// until nothing involved moves more than the tolerance inside the bracket. The bodies are left
    /// at some time of the bracket.
    /// </summary>
    public double Search(double free, double hit, bool knownApart, BodySet involved)
    {
        float rate = 0f;
        foreach (int slot in hits.Slot)
        {
            rate = MathF.Max(rate, _table.Rate(slot));
        }

        if (!knownApart)
        {
            MoveInvolved(free, involved);
            if (AnyHitIntersects())
            {
                return free;
            }
        }

        double lo = free;
        double hi = hit;
        if ((hi - lo) * rate > MotionTolerances.TimeOfImpactTolerance)
        {
            Guess(ref lo, ref hi, rate, involved);
        }
        for (int iteration = 0; iteration < 48 && (hi - lo) * rate > MotionTolerances.TimeOfImpactTolerance; iteration++)
        {
            double mid = 0.5 * (lo + hi);
            MoveInvolved(mid, involved);
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

    // The deepest hit's depth shrinks at its closing rate, so it reached zero near hi − depth / rate:
    // probe there (exact for translation). While the probe still overlaps, the same estimate from
    // its own depth moves hi on (a few rounds: turning bodies close at a changing rate); once a
    // probe is apart, one more just after it brackets the contact tightly.
    private void Guess(ref double lo, ref double hi, float rate, BodySet involved)
    {
        int deepest = 0;
        ReadOnlySpan<Hit> values = hits.Value;
        for (int i = 1; i < values.Length; i++)
        {
            deepest = values[i].Depth > values[deepest].Depth ? i : deepest;
        }

        int slot = hits.Slot[deepest];
        Hit hit = values[deepest];
        for (int round = 0; round < GuessRounds; round++)
        {
            float closing = ClosingRate(_table.Pair(slot), hit);
            if (!(closing > 0f) || rate <= 0f)
            {
                return;
            }

            double guess = hi - (hit.Depth / closing);
            if (!(guess > lo && guess < hi))
            {
                return;
            }

            MoveInvolved(guess, involved);
            if (DeepestHitNow(out slot, out hit))
            {
                hi = guess;
                if ((hi - lo) * rate <= MotionTolerances.TimeOfImpactTolerance)
                {
                    return;
                }

                continue;
            }

            lo = guess;
            double next = lo + (0.5 * MotionTolerances.TimeOfImpactTolerance / rate);
            if (next < hi)
            {
                MoveInvolved(next, involved);
                if (AnyHitIntersects())
                {
                    hi = next;
                }
                else
                {
                    lo = next;
                }
            }

            return;
        }
    }

    // The deepest of the event's pairs that overlaps now, if any.
    private bool DeepestHitNow(out int slot, out Hit deepest)
    {
        slot = -1;
        deepest = default;
        foreach (int hitSlot in hits.Slot)
        {
            ref readonly PlannedPair pair = ref _table.Pair(hitSlot);
            Hit hit = _sampler.Memo.DetectIfNear(bodies[pair.A], bodies[pair.B]);
            if (hit.Depth > MotionTolerances.ContactSlop && hit.Depth > deepest.Depth)
            {
                slot = hitSlot;
                deepest = hit;
            }
        }

        return slot >= 0;
    }

    private bool AnyHitIntersects()
    {
        foreach (int slot in hits.Slot)
        {
            ref readonly PlannedPair pair = ref _table.Pair(slot);
            if (_sampler.Memo.DetectIfNear(bodies[pair.A], bodies[pair.B]).Depth > MotionTolerances.ContactSlop)
            {
                return true;
            }
        }

        return false;
    }

    // How fast the two bodies close along the hit's normal at its action point, mm per whole step (positive when approaching).
    private float ClosingRate(in PlannedPair pair, in Hit hit)
    {
        Vector2 a = PointVelocity(bodies[pair.A], hit.Point);
        Vector2 b = pair.MoverB >= 0 ? PointVelocity(bodies[pair.B], hit.Point) : Vector2.Zero;
        return -Vector2.Dot(a - b, hit.Normal) * schedule.Seconds;
    }

    private static Vector2 PointVelocity(Body body, Vector2 point)
    {
        Vector2 r = point - body.Position;
        return body.Velocity + (body.AngularVelocity * new Vector2(-r.Y, r.X));
    }

    // The event's bodies placed at a time of the step.
    private void MoveInvolved(double time, BodySet involved)
    {
        float seconds = schedule.Seconds;
        foreach (int m in involved.Items)
        {
            schedule.Planner.MoverBodies[m].MoveTo(time, seconds);
        }
    }
}
