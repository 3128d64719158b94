using System;

namespace URWPGSim2D.Server.Simulation;

/// <content>Resolving overlaps without motion, and measuring them.</content>
internal sealed partial class Stepper
{
    /// <summary>
    /// Resolves overlaps left by a discontinuous change (balls put back at their start after a
    /// goal): every body, a few passes of position correction and impulses without motion, then
    /// measures the leftover.
    /// </summary>
    public void Settle()
    {
        _unsettled.Clear();
        for (int m = 0; m < _planner.Movers; m++)
        {
            _unsettled.Add(m);
        }

        LeftoverOverlap = SettleMovers(_unsettled);
    }

    /// <summary>Deepest overlap among all pairs the broad phase finds now (no motion), mm.</summary>
    public float MeasureOverlap()
    {
        _collector.Clear();
        _planner.PlanAll(1.0, _collector);
        float deepest = 0f;
        foreach (ref readonly var pair in _collector.Pairs)
        {
            deepest = MathF.Max(deepest, Detect(pair).Depth);
        }

        return deepest;
    }

    // Up to SettlePasses passes over the pairs of `set` at the end of the cycle: overlaps are resolved and
    // the bodies that moved are checked again; returns the deepest overlap left among them.
    private float SettleMovers(MoverSet set)
    {
        MoverSet current = set;
        MoverSet next = _involved;
        for (int pass = 0; pass < PhysicsConstants.SettlePasses; pass++)
        {
            next.Clear();
            _collector.Clear();
            _planner.PlanFor(current.Items, current.Marks, 1.0, _collector);
            float deepest = 0f;
            foreach (ref readonly var pair in _collector.Pairs)
            {
                Hit hit = Detect(pair);
                if (hit.Depth <= PhysicsConstants.ContactSlop)
                {
                    deepest = MathF.Max(deepest, hit.Depth);
                    continue;
                }

                hit = PairDetector.Detect(_world, pair);
                ContactKind kind = _response.Apply(pair, hit);
                _log.Add(new ContactRecord(pair, hit.PartA, hit.PartB, hit.Mtv, hit.Normal, hit.Point, 1.0), kind);
                MarkInto(next, pair);
            }

            if (next.Count == 0)
            {
                current.Clear();
                return deepest;
            }

            current.Clear();
            (current, next) = (next, current);
        }

        _collector.Clear();
        _planner.PlanFor(current.Items, current.Marks, 1.0, _collector);
        float left = 0f;
        foreach (ref readonly var pair in _collector.Pairs)
        {
            left = MathF.Max(left, Detect(pair).Depth);
        }

        current.Clear();
        return left;
    }

    private void MarkInto(MoverSet set, in CandidatePair p)
    {
        int fish = _planner.FishCount;
        switch (p.Kind)
        {
            case PairKind.FishFish:
                set.Add(p.A);
                set.Add(p.B);
                break;
            case PairKind.FishBall:
                set.Add(p.A);
                set.Add(fish + p.B);
                break;
            case PairKind.BallBall:
                set.Add(fish + p.A);
                set.Add(fish + p.B);
                break;
            case PairKind.FishStatic:
            case PairKind.FishWall:
                set.Add(p.A);
                break;
            default:
                set.Add(fish + p.A);
                break;
        }
    }
}
