namespace URWPGSim2D.Collision.Motion;

/// <summary>
/// When the motion world counts a moving body as wedged (pushed back and forth between others without
/// getting free), and what it does then. A wedged body's further contacts that cannot tunnel
/// before the step ends are left to the end of the step, where settling tries to free it; a body
/// still overlapping there has its move rejected (back where it began the step, at rest). The
/// position corrections a handler makes in <see cref="IContactHandler.OnSeparate"/> are counted by
/// the motion world itself: a body with too many deep ones in the step has its move rejected at once. The defaults suit
/// the match server; <see cref="MotionWorld.Wedging"/> sets another policy.
/// </summary>
public sealed class WedgePolicy
{
    private readonly int _eventsBeforeDeferring = 16;
    private readonly int _eventsInPlaceBeforeDeferring = 2;
    private readonly int _correctionsBeforeRejecting = 8;

    /// <summary>Contact events a body may take part in per step before it counts as wedged (16; at least 1).</summary>
    /// <exception cref="ArgumentException">The value is less than 1.</exception>
    public int EventsBeforeDeferring
    {
        get => _eventsBeforeDeferring;
        init => _eventsBeforeDeferring = AtLeast(1, value, "eventsBeforeDeferring");
    }

    /// <summary>Contact events in a row at one time (pushed back and forth in place) after which a body counts as wedged (2; at least 1).</summary>
    /// <exception cref="ArgumentException">The value is less than 1.</exception>
    public int EventsInPlaceBeforeDeferring
    {
        get => _eventsInPlaceBeforeDeferring;
        init => _eventsInPlaceBeforeDeferring = AtLeast(1, value, "eventsInPlaceBeforeDeferring");
    }

    /// <summary>
    /// Deep position corrections (of a contact deeper than <see cref="MotionTolerances.TimeOfImpactTolerance"/>,
    /// made by <see cref="IContactHandler.OnSeparate"/>; a fish's or a polygon's; a pressing contact's,
    /// <see cref="Contact.Pressing"/>, never counts) a body may have in one step, a
    /// <see cref="MotionWorld.Settle"/> after it included; the next one rejects its move (8; at least 0).
    /// </summary>
    /// <exception cref="ArgumentException">The value is negative.</exception>
    public int CorrectionsBeforeRejecting
    {
        get => _correctionsBeforeRejecting;
        init => _correctionsBeforeRejecting = AtLeast(0, value, "correctionsBeforeRejecting");
    }

    /// <summary>Whether a body's events this step make it wedged.</summary>
    internal bool Wedged(int events, int eventsInPlace) =>
        events >= _eventsBeforeDeferring || eventsInPlace >= _eventsInPlaceBeforeDeferring;

    private static int AtLeast(int least, int value, string name) =>
        value >= least ? value : throw new ArgumentException($"{name} must be at least {least}, got {value}", name);
}
