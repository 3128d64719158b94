using System;
using System.Numerics;
using URWPGSim2D.Collision.Fish;

namespace URWPGSim2D.Collision.Benchmarks.Baseline.Motion;

/// <summary>
/// The time of first contact of two bodies moving rigidly over an interval (the pair-level form
/// of the <see cref="Stepper"/>'s detection). The pair is sampled often enough that it cannot
/// pass through itself between two samples (its relative travel between samples stays within
/// half the sum of the two bodies' thinnest widths), and not at all while their bounding circles
/// are too far apart to meet; the first overlapping sample is refined by bisection until nothing
/// moves more than 0.25 mm inside the bracket. A fish's joints keep their angles throughout.
/// </summary>
internal static class TimeOfImpact
{
    /// <summary>The first time in [0, <paramref name="seconds"/>] at which the two bodies overlap, with the contact then.</summary>
    /// <param name="a">The first body (its MTV is reported).</param>
    /// <param name="b">The second body.</param>
    /// <param name="seconds">Length of the interval, s (positive and finite).</param>
    /// <returns>The contact at its time of first contact, or <see cref="TimeOfImpactResult.NoContact"/>.</returns>
    /// <exception cref="ArgumentException">Both bodies are static (or walls), a body is default, or <paramref name="seconds"/> is not positive and finite.</exception>
    public static TimeOfImpactResult Find(in MovingBody a, in MovingBody b, float seconds)
    {
        if (!(seconds > 0f) || float.IsPositiveInfinity(seconds))
        {
            throw new ArgumentException($"interval must be positive and finite, got {seconds}", nameof(seconds));
        }

        Body first = ToBody(a, 0, nameof(a));
        Body second = ToBody(b, 1, nameof(b));
        bool swap = !first.IsMoving;
        if (swap)
        {
            (first, second) = (second, first);
        }

        if (!first.IsMoving)
        {
            throw new ArgumentException("at least one body must move (both are static)", nameof(b));
        }

        FishPose? poseA = first.Model?.Pose, poseB = second.Model?.Pose;
        try
        {
            TimeOfImpactResult found = Search(first, second, seconds, out Hit hit, out double time);
            if (!found.Hit)
            {
                return found;
            }

            return new TimeOfImpactResult((float)(time * seconds), swap ? hit.Swapped() : hit);
        }
        finally
        {
            if (poseA.HasValue)
            {
                first.Model!.SetPose(poseA.Value);
            }

            if (poseB.HasValue)
            {
                second.Model!.SetPose(poseB.Value);
            }
        }
    }

    private static TimeOfImpactResult Search(Body a, Body b, float seconds, out Hit hit, out double time)
    {
        time = 0.0;
        hit = PairTest.Detect(a, b);
        if (hit.Depth > MotionTolerances.ContactSlop)
        {
            return new TimeOfImpactResult(0f, hit);
        }

        Vector2 relative = a.Velocity - (b.IsMoving ? b.Velocity : Vector2.Zero);
        float rate = (relative.Length() * seconds) + Spin(a, seconds) + Spin(b, seconds);
        if (!(rate > 0f))
        {
            return TimeOfImpactResult.NoContact;
        }

        float limit = 0.5f * (a.Thickness + b.Thickness);
        double interval = float.IsPositiveInfinity(limit) ? 1.0 : Math.Min(1.0, limit / (double)rate);
        interval = Math.Max(interval, 1.0 / TickQueue.Ticks);
        double t = 0.0;
        while (t < 1.0)
        {
            float gap = PairTest.Gap(a, b);
            double step = gap > 0f ? Math.Max(interval, gap / (double)rate) : interval;
            if (gap > 0f && t + (gap / (double)rate) >= 1.0)
            {
                return TimeOfImpactResult.NoContact;
            }

            double next = Math.Min(1.0, t + step);
            MoveTo(a, b, next, seconds);
            if (PairTest.DetectIfNear(a, b).Depth > MotionTolerances.ContactSlop)
            {
                time = Refine(a, b, t, next, rate, seconds);
                MoveTo(a, b, time, seconds);
                hit = PairTest.Detect(a, b);
                return new TimeOfImpactResult((float)time, hit);
            }

            t = next;
        }

        return TimeOfImpactResult.NoContact;
    }

    // Bisection between a free time and an overlapping one, to the tolerance in travel.
    private static double Refine(Body a, Body b, double lo, double hi, float rate, float seconds)
    {
        for (int i = 0; i < 48 && (hi - lo) * rate > MotionTolerances.TimeOfImpactTolerance; i++)
        {
            double mid = 0.5 * (lo + hi);
            MoveTo(a, b, mid, seconds);
            if (PairTest.DetectIfNear(a, b).Depth > MotionTolerances.ContactSlop)
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

    private static void MoveTo(Body a, Body b, double time, float seconds)
    {
        a.MoveTo(time, seconds);
        if (b.IsMoving)
        {
            b.MoveTo(time, seconds);
        }
    }

    // The most any point of the body moves over the interval by turning, mm.
    private static float Spin(Body body, float seconds)
    {
        if (body.Kind is not (BodyKind.Polygon or BodyKind.Fish))
        {
            return 0f;
        }

        Disc bound = body.Bound();
        float reach = Vector2.Distance(bound.Center, body.Position) + bound.Radius;
        return MathF.Abs(body.AngularVelocity) * reach * seconds;
    }

    private static Body ToBody(in MovingBody m, int id, string name)
    {
        Body body = m.Kind switch
        {
            BodyKind.Circle => Body.Circle(id, m.CircleShape.Radius, m.CircleShape.Center),
            BodyKind.Polygon => m.Outline.Vertices.Length > 0 ? Body.Polygon(id, m.Outline, m.Position, m.Heading) : throw new ArgumentException("polygon is default(ConvexPolygon)", name),
            BodyKind.Fish => Body.Fish(id, m.Model ?? throw new ArgumentException("body is default(MovingBody)", name)),
            BodyKind.Static => Body.Static(id, m.StaticShape),
            _ => Body.Walls(id, m.Field ?? throw new ArgumentException("body is default(MovingBody)", name)),
        };
        if (m.Kind == BodyKind.Circle && m.CircleShape.Radius <= 0f)
        {
            throw new ArgumentException("body is default(MovingBody)", name);
        }

        body.Velocity = m.Velocity;
        body.AngularVelocity = m.Kind == BodyKind.Circle ? 0f : m.AngularVelocity;
        body.Rebase(0.0);
        return body;
    }
}
