namespace URWPGSim2D.Collision.Motion;

/// <summary>
/// The motion world's tolerances (mm): how deep an overlap may be and still count as touching, and how
/// closely the time of first contact is found. A contact response plugged into the motion world uses
/// them to tell a resolved pair and a refined contact; the work limits stay the motion world's own.
/// </summary>
public static class MotionTolerances
{
    /// <summary>Overlaps up to this depth (mm) count as touching: no event.</summary>
    public const float ContactSlop = 0.01f;

    /// <summary>The search for the time of first contact stops when nothing involved moves more than this (mm) inside its bracket.</summary>
    public const float TimeOfImpactTolerance = 0.25f;

    /// <summary>Overlap (mm) above which a body's move is rejected at the end of a step (the guarantee is 0.5 mm).</summary>
    internal const float RejectOverlap = 0.4f;

    /// <summary>Contact events a body may take part in per step with a refined time of first contact; later ones are resolved where found.</summary>
    internal const int MaximumEventsPerBody = 64;

    /// <summary>Passes of immediate re-resolution after a contact when a response pushes a body into a third one.</summary>
    internal const int RelaxationPasses = 8;

    /// <summary>Passes of resolution without motion at the end of a step.</summary>
    internal const int SettlePasses = 16;
}
