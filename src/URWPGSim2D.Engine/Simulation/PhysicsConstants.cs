namespace URWPGSim2D.Engine.Simulation;

/// <summary>
/// The reference's physical constants and the server's response limits (mm, s, reference mass
/// units). The motion world's own tolerances (contact slop, time-of-impact tolerance) are the
/// library's <c>MotionTolerances</c>, which the response uses too.
/// </summary>
internal static class PhysicsConstants
{
    /// <summary>One cycle of simulated time, s.</summary>
    public const float CycleSeconds = 0.1f;

    /// <summary>Fish mass (reference units).</summary>
    public const float FishMass = 0.8f;

    /// <summary>Ball mass (reference units).</summary>
    public const float BallMass = 0.49f;

    /// <summary>Fish moment of inertia in the reference's turning rule Δω = J·r⊥ / 6000.</summary>
    public const float FishInertia = 6000f;

    /// <summary>
    /// The time over which the original applies a contact's turning impulse, s: heading += Δω·0.01
    /// (a heading increment, never a change of the fish's angular speed).
    /// </summary>
    public const float TurnImpulseSeconds = 0.01f;

    /// <summary>Fish–ball restitution at the head tip: e = −0.005·(1 − d/300), d from the head tip along the axis.</summary>
    public const float FishBallRestitution = -0.005f;

    /// <summary>Fish–fish restitution at both head tips: e' = −0.005·(1 − (d_A + d_B)/600).</summary>
    public const float FishFishRestitution = -0.005f;

    /// <summary>The distance along the fish axis (mm) over which the fish restitutions fall to 0 (600 for two fish).</summary>
    public const float RestitutionReach = 300f;

    /// <summary>Ball–ball restitution (equal masses, practically inelastic).</summary>
    public const float BallBallRestitution = 0.005f;

    /// <summary>A ball's normal speed against a wall or goal block is multiplied by this.</summary>
    public const float BallWallFactor = -0.001f;

    /// <summary>A ball's normal speed against an obstacle is multiplied by this.</summary>
    public const float BallObstacleFactor = -0.1f;

    /// <summary>A fish's normal speed against an obstacle becomes this·(1 − d/300)·v_n.</summary>
    public const float FishObstacleFactor = -0.003f;

    /// <summary>The ball's share of a fish–ball position correction when a pectoral fin hit it (else one half).</summary>
    public const float PectoralBallShare = 0.75f;

    /// <summary>Below this speed (mm/s) a fish cannot turn.</summary>
    public const float MinimumTurningSpeed = 2f;

    /// <summary>Extra gap (mm) left by a position correction so a resolved pair is not found again.</summary>
    public const float SeparationMargin = 0.01f;
}
