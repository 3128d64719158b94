using URWPGSim2D.Collision.Fish;

namespace URWPGSim2D.Collision.Benchmarks.Baseline.Motion;

/// <summary>The answer of <see cref="TimeOfImpact.Find"/>: when two moving bodies first touch, and how.</summary>
internal readonly struct TimeOfImpactResult
{
    internal TimeOfImpactResult(float time, in Hit hit)
    {
        Hit = true;
        Time = time;
        Result = hit.Result;
        PartA = hit.PartA < 0 ? null : (FishPart)hit.PartA;
        PartB = hit.PartB < 0 ? null : (FishPart)hit.PartB;
    }

    /// <summary>The answer for bodies that do not touch within the interval.</summary>
    public static TimeOfImpactResult NoContact => default;

    /// <summary>Whether the bodies touch within the interval.</summary>
    public bool Hit { get; }

    /// <summary>Time of first contact from the start of the interval, s (0 when they already overlap at the start).</summary>
    public float Time { get; }

    /// <summary>The contact at that time (MTV moves the first body), overlapping by at most the tolerance.</summary>
    public CollisionDetectionResult Result { get; }

    /// <summary>The first body's leaf in contact when it is a fish.</summary>
    public FishPart? PartA { get; }

    /// <summary>The second body's leaf in contact when it is a fish.</summary>
    public FishPart? PartB { get; }
}
