namespace URWPGSim2D.Server.Simulation;

/// <summary>The reference's physical constants and the stepper's tolerances (mm, s, reference mass units).</summary>
internal static class PhysicsConstants
{
    /// <summary>One cycle of simulated time, s.</summary>
    public const float CycleSeconds = 0.1f;

    /// <summary>Fish mass (reference units).</summary>
    public const float FishMass = 0.8f;

    /// <summary>Ball mass (reference units).</summary>
    public const float BallMass = 0.49f;

    /// <summary>Fish moment of inertia in the reference's spin rule Δω = J·r⊥ / 6000.</summary>
    public const float FishInertia = 6000f;

    /// <summary>Fish–fish and ball–ball restitution (almost perfectly inelastic).</summary>
    public const float MovingPairRestitution = 0.005f;

    /// <summary>Ball against a wall or goal block.</summary>
    public const float BallWallRestitution = 0.001f;

    /// <summary>Ball against an obstacle.</summary>
    public const float BallObstacleRestitution = 0.1f;

    /// <summary>Below this speed (mm/s) a fish cannot turn.</summary>
    public const float MinimumTurningSpeed = 2f;

    /// <summary>Overlaps up to this depth (mm) count as touching: no event, no correction.</summary>
    public const float ContactSlop = 0.01f;

    /// <summary>Extra gap (mm) left by a position correction so a resolved pair is not found again.</summary>
    public const float SeparationMargin = 0.01f;

    /// <summary>Bisection stops when nothing involved moves more than this (mm) inside the bracket.</summary>
    public const float TimeOfImpactTolerance = 0.25f;

    /// <summary>
    /// Contact events a body may take part in per cycle with a refined time of first contact; its
    /// later events in that cycle are resolved where they are found (bounds the work in a jam).
    /// </summary>
    public const int MaximumEventsPerBody = 64;

    /// <summary>Passes of immediate re-resolution after a contact when a correction pushes a body into a third one.</summary>
    public const int RelaxationPasses = 8;

    /// <summary>Passes of the settling without motion at the end of a cycle (and after goals).</summary>
    public const int SettlePasses = 8;

    /// <summary>Position corrections a fish may take in one cycle before its move is rejected.</summary>
    public const int MaximumCorrectionsPerFish = 8;

    /// <summary>Largest number of sub-steps per cycle.</summary>
    public const int MaximumSubSteps = 2048;
}
