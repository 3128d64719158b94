namespace URWPGSim2D.Collision.Motion;

/// <summary>The answer of <see cref="TimeOfImpact.Find"/>: when two moving bodies first touch, and how.</summary>
public readonly struct TimeOfImpactResult
{
    // The motion world's contact, seen from the query's first body (swap: the contact's A is the query's second body).
    internal TimeOfImpactResult(float time, in Contact contact, bool swap)
    {
        Hit = true;
        Time = time;
        Result = swap ? contact.Result.Swapped() : contact.Result;
        PartA = swap ? contact.PartB : contact.PartA;
        PartB = swap ? contact.PartA : contact.PartB;
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
