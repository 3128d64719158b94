namespace URWPGSim2D.Engine.Simulation;

/// <summary>
/// The original's velocity exchange along a contact normal and its turning rule. Velocities are
/// split into a normal part (along the unit normal) and a tangential part, which is kept. Two
/// bodies with normal speeds v₁, v₂ and masses m₁, m₂ exchange as
/// v₁' = (m₁·v₁ + m₂·(v₂ + e·(v₂ − v₁))) / (m₁ + m₂) (and v₂' likewise), so the relative normal speed
/// becomes −e times itself: e = 0 is perfectly inelastic, a negative e leaves the bodies still
/// closing slightly. A fish struck with impulse J (magnitude m·|Δv_n|) at lever r turns by
/// Δω = J·r⊥ / 6000 applied as a heading increment Δω·0.01 s, with r⊥ = r × (unit impulse on the
/// fish) signed, so the struck point moves away from what struck it.
/// </summary>
internal static class Impulse
{
    /// <summary>2D cross product a.x·b.z − a.z·b.x.</summary>
    public static float Cross(Vector2 a, Vector2 b) => (a.X * b.Y) - (a.Y * b.X);

    /// <summary>Velocity of a point at lever arm r on a body turning at ω (rad/s, positive from +X toward +Z).</summary>
    public static Vector2 PointVelocity(Vector2 v, float omega, Vector2 r) => v + (omega * new Vector2(-r.Y, r.X));

    /// <summary>Body 1's normal speed after the exchange (see the type's summary).</summary>
    /// <param name="v1">Body 1's normal speed before.</param>
    /// <param name="m1">Body 1's mass.</param>
    /// <param name="v2">Body 2's normal speed before.</param>
    /// <param name="m2">Body 2's mass.</param>
    /// <param name="restitution">The exchange's e (the original's sign convention).</param>
    public static float Exchange(float v1, float m1, float v2, float m2, float restitution) =>
        ((m1 * v1) + (m2 * (v2 + (restitution * (v2 - v1))))) / (m1 + m2);

    /// <summary>
    /// The heading increment (rad) of a fish that receives <paramref name="impulse"/> (mass × velocity
    /// change, a vector) at lever arm <paramref name="lever"/> from its position: Δω·0.01 s with
    /// Δω = (r × impulse) / 6000 = J·r⊥ / 6000.
    /// </summary>
    /// <param name="lever">Action point minus the fish's position, mm.</param>
    /// <param name="impulse">The impulse on the fish, reference mass units × mm/s.</param>
    public static float HeadingIncrement(Vector2 lever, Vector2 impulse) =>
        Cross(lever, impulse) / PhysicsConstants.FishInertia * PhysicsConstants.TurnImpulseSeconds;
}
