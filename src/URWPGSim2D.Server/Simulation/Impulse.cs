using System.Numerics;

namespace URWPGSim2D.Server.Simulation;

/// <summary>
/// The normal impulse of a contact between two bodies with linear and angular velocity:
/// the relative velocity of the contact point is split into normal and tangential parts; the
/// tangential part is kept and the normal part becomes −e times itself. For unit normal n (from B
/// toward A), lever arms rA, rB and point velocities vA + ωA·perp(rA) (perp(r) = (−r_z, r_x)),
/// J = −(1 + e)·vn / (1/mA + 1/mB + (rA×n)²/IA + (rB×n)²/IB) when vn &lt; 0 (approaching), else 0.
/// A gets +J·n (Δω_A = rA×(J·n)/IA, the reference's J·r⊥/6000 spin rule), B gets −J·n.
/// A zero inverse mass is a static body. Linear momentum along n is conserved.
/// </summary>
internal static class Impulse
{
    /// <summary>2D cross product a.x·b.z − a.z·b.x.</summary>
    public static float Cross(Vector2 a, Vector2 b) => (a.X * b.Y) - (a.Y * b.X);

    /// <summary>Velocity of a point at lever arm r on a body turning at ω (rad/s, positive from +X toward +Z).</summary>
    public static Vector2 PointVelocity(Vector2 v, float omega, Vector2 r) => v + (omega * new Vector2(-r.Y, r.X));

    /// <summary>The impulse magnitude J ≥ 0 along n (see the type's summary).</summary>
    public static float Magnitude(
        Vector2 n, float restitution,
        Vector2 velocityA, float omegaA, Vector2 leverA, float inverseMassA, float inverseInertiaA,
        Vector2 velocityB, float omegaB, Vector2 leverB, float inverseMassB, float inverseInertiaB)
    {
        Vector2 relative = PointVelocity(velocityA, omegaA, leverA) - PointVelocity(velocityB, omegaB, leverB);
        float vn = Vector2.Dot(relative, n);
        if (vn >= 0f)
        {
            return 0f;
        }

        float ka = Cross(leverA, n);
        float kb = Cross(leverB, n);
        float denominator = inverseMassA + inverseMassB + (ka * ka * inverseInertiaA) + (kb * kb * inverseInertiaB);
        return denominator > 0f ? -(1f + restitution) * vn / denominator : 0f;
    }
}
