using URWPGSim2D.Engine.Simulation.Kinematics;

namespace URWPGSim2D.Engine.Items.Demo;

/// <summary>
/// A ball's position as a strategy can best know it, and the impulse it took last cycle. The view's
/// position is noisy (±30 mm per axis) but its velocity is exact: the estimate is carried by the
/// velocity and pulled toward the view by a Kalman gain. The velocity also tells when something hit
/// the ball: after the cycle's drag is undone, the change from the last view's velocity is the
/// contact impulse, which is along the contact normal (tangential parts are kept). A pusher uses that
/// direction to place the ball on its head far more precisely than the position view can
/// (<see cref="Contact"/>). A view more than 150 mm from the estimate restarts it.
/// </summary>
internal struct BallTrack
{
    private const float ViewVariance = 30f * 30f / 3f;
    private const float Dt = 0.1f;

    private float _variance;
    private Vector2 _lastVelocity;

    /// <summary>The estimated centre, mm.</summary>
    public Vector2 Position;

    /// <summary>The ball's velocity (exact), mm/s.</summary>
    public Vector2 Velocity;

    /// <summary>The change of velocity by contacts during the last cycle, mm/s (zero when nothing hit it).</summary>
    public Vector2 Impulse;

    /// <summary>Whether the track has seen the ball.</summary>
    public bool Started;

    /// <summary>Takes this cycle's view of the ball.</summary>
    public void Update(in BallView view)
    {
        Impulse = Started ? Undrag(view.Velocity, _lastVelocity) - _lastVelocity : Vector2.Zero;
        _lastVelocity = view.Velocity;
        Velocity = view.Velocity;
        if (!Started || Vector2.Distance(view.Position, Position) > 150f)
        {
            Position = view.Position;
            _variance = ViewVariance;
            Impulse = Vector2.Zero;
            Started = true;
            return;
        }

        Position += view.Velocity * Dt;
        _variance += Impulse.LengthSquared() > 4f ? 29f : 4f;
        float gain = _variance / (_variance + ViewVariance);
        Position += gain * (view.Position - Position);
        _variance *= 1f - gain;
    }

    /// <summary>Pulls the estimate toward where a contact says the centre is.</summary>
    /// <param name="centre">The centre the contact implies.</param>
    /// <param name="gain">How far toward it (0..1).</param>
    public void Contact(Vector2 centre, float gain)
    {
        Position += gain * (centre - Position);
        _variance *= 1f - gain;
    }

    // The velocity before this cycle's drag (the drag keeps the direction and takes a speed step by
    // band). Two bands can lead to the same speed (85 mm/s comes from 110 or from 95): take the one
    // nearest the last velocity, i.e. the smaller impulse.
    private static Vector2 Undrag(Vector2 velocity, Vector2 last)
    {
        float speed = velocity.Length();
        if (speed < 1e-3f)
        {
            // At rest now: a slow ball may simply have stopped in this cycle's drag.
            return last.Length() <= (BandDeceleration(3) * Dt) + 1e-3f ? last : velocity;
        }

        Vector2 best = velocity;
        float bestMiss = float.PositiveInfinity;
        for (int band = 0; band < 4; band++)
        {
            float before = speed + (BandDeceleration(band) * Dt);
            if (BallMotion.Deceleration(before) != BandDeceleration(band))
            {
                continue;
            }

            Vector2 candidate = velocity * (before / speed);
            float miss = Vector2.DistanceSquared(candidate, last);
            if (miss < bestMiss)
            {
                best = candidate;
                bestMiss = miss;
            }
        }

        return best;
    }

    private static float BandDeceleration(int band) => band switch { 0 => 250f, 1 => 100f, 2 => 25f, _ => 6.25f };
}
