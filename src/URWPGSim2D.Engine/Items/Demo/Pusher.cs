using URWPGSim2D.Collision.Motion;
using URWPGSim2D.Engine.Simulation.Kinematics;

namespace URWPGSim2D.Engine.Items.Demo;

/// <summary>
/// Pushes a ball in a wanted direction with a fish that turns slowly and late, and keeps it on the
/// fish's pointed head. On the head the ball is balanced like an inverted pendulum: at speed v a ball
/// at angle α from the heading (seen from the head tip) slides off at dα/dt ≈ (v/r)·α − (1 + h/r)·ω
/// (r the ball radius, h the tip's distance from the centre, ω the turn rate), and ω itself follows
/// the turn code with a one-second lag. The controller places both poles of that loop at −1.2/s:
/// the turn it asks for is ω_ref + k₁(α − α_ref) + k₂(ω − ω_ref) + kᵢ∫(α − α_ref) with
/// k₁ = (p + a)²/b, k₂ = 1 − 2p − a (a = ball speed / r, b = 1 + h/r, p = 1.2); the integral takes out
/// what the model gets wrong. To curve the ball's path toward the wanted direction it holds the ball
/// to the inside of the turn: a path curvature κ (the error of the ball's own direction over 250 mm,
/// at most 0.6/(r·b): a radius of about 300 mm) needs ω_ref = κv and α_ref = κ·r·b. It slows down
/// in a turn and while the ball is off its place. α is measured where it is sharpest: the ball's
/// exact velocity gives the contact impulse, which points from the tip to the ball's centre
/// (<see cref="BallTrack"/>). A fish not behind its ball gets there with <see cref="Approach"/> (a
/// point 200 mm behind the ball on the push line), then runs up along the line; a ball against a
/// wall is first pushed out along it. One value per fish, kept across cycles.
/// </summary>
internal struct Pusher
{
    /// <summary>Where the loop's poles are placed, 1/s.</summary>
    public const float Pole = 1.2f;

    /// <summary>Largest angle at which the ball is held off the heading to curve its path, rad.</summary>
    public const float MaxHold = 0.6f;

    /// <summary>Distance over which the heading error is turned away, mm (sets the path's curvature).</summary>
    public const float TurnDistance = 250f;

    /// <summary>Heading error (rad) beyond which the push slows to gear 3 (twice that: gear 2), to round a corner tightly.</summary>
    public const float SlowError = 0.3f;

    /// <summary>Heading error (rad) beyond which a fish pushing its ball gives up and comes round again.</summary>
    public const float ExitError = 2.2f;

    /// <summary>Gain of the integral of α's error (it takes out the model's mismatch, so the held angle is reached), 1/s².</summary>
    public const float Integral = 0.8f;

    /// <summary>Gap between the head tip and the ball where the approach ends and the run-up along the push line begins, mm.</summary>
    public const float RunUp = 200f;

    private bool _pushing;
    private bool _runUp;
    private float _integral;
    private Approach _approach;

    /// <summary>Whether the fish has the ball on its head (or is about to).</summary>
    public readonly bool Pushing => _pushing;

    /// <summary>The decision pushing the ball of <paramref name="ball"/> along <paramref name="direction"/>.</summary>
    /// <param name="view">The fish as seen.</param>
    /// <param name="me">The fish's estimated pose.</param>
    /// <param name="ball">The ball's track (a contact on the head refines it).</param>
    /// <param name="radius">Ball radius, mm.</param>
    /// <param name="direction">Where the ball should go (a unit vector).</param>
    /// <param name="around">Walls and obstacles, for the approach.</param>
    /// <param name="pushVCode">Speed gear while pushing.</param>
    public Decision Push(in FishView view, in FishTrack me, ref BallTrack ball, float radius, Vector2 direction, in Surroundings around, int pushVCode)
    {
        float reach = (view.BodyLength * 0.5f) + view.HeadLength;
        Vector2 u = me.Forward;
        Vector2 tip = me.Position + (u * reach);
        Sharpen(me, tip, ref ball, radius);

        Vector2 toBall = ball.Position - tip;
        float gap = toBall.Length() - radius;
        float alpha = Angle.Wrap(MathF.Atan2(toBall.Y, toBall.X) - me.Heading);
        float error = Angle.Wrap(MathF.Atan2(direction.Y, direction.X) - me.Heading);
        _pushing = _pushing
            ? gap < 200f && MathF.Abs(alpha) < 1.1f && MathF.Abs(error) < ExitError
            : gap < 150f && MathF.Abs(alpha) < 0.7f && MathF.Abs(error) < 1.0f;
        if (!_pushing)
        {
            _integral = 0f;
            direction = Open(direction, ball.Position, radius + reach + RunUp, around);
            float wanted = MathF.Atan2(direction.Y, direction.X);
            Vector2 side = new(-direction.Y, direction.X);
            Vector2 fromBall = tip - ball.Position;
            float along = Vector2.Dot(fromBall, direction), aside = Vector2.Dot(fromBall, side);
            error = Angle.Wrap(wanted - me.Heading);
            _runUp = _runUp
                ? along < -radius * 0.3f && along > -(radius + RunUp + 500f) && MathF.Abs(aside) < 40f - (0.8f * along) && MathF.Abs(error) < 1.0f
                : along < -(radius + 20f) && along > -(radius + RunUp + 400f) && MathF.Abs(aside) < -0.6f * along && MathF.Abs(error) < 0.8f;
            if (_runUp)
            {
                // On the push line behind the ball: follow it with the head tip (Stanley-type) up to the ball.
                float heading = wanted - MathF.Atan2(aside, 150f);
                float want = Math.Clamp(1.2f * Angle.Wrap(heading - me.Heading), -0.35f, 0.35f);
                return new Decision(gap > 250f ? 4 : Math.Min(pushVCode, 3), TurnCode.For(want, view.AngularSpeed));
            }

            Vector2 goal = ball.Position - (direction * (radius + reach + RunUp));
            if (!around.Ways.Free(me.Position, goal, Approach.WallMargin) && Vector2.Distance(me.Position, goal) > 300f)
            {
                // Obstacles in between: round them first.
                return Travel(view, me, goal, around);
            }

            return _approach.Toward(view, me, goal, wanted, around, ball.Position, radius, 4, RunUp - 60f, 300f);
        }

        float b = 1f + (reach / radius);
        float limit = MaxHold / (radius * b);
        float curvature = Math.Clamp(Angle.Wrap(error - alpha) / TurnDistance, -limit, limit);
        float speed = MathF.Max(view.Speed, 10f);
        float a = MathF.Max(ball.Velocity.Length(), 0.75f * speed) / radius;
        float hold = curvature * radius * b;
        float rateRef = curvature * speed;
        float k1 = (Pole + a) * (Pole + a) / b, k2 = 1f - (2f * Pole) - a;
        _integral = Math.Clamp(_integral + ((alpha - hold) * 0.1f), -0.5f, 0.5f);
        float rate = rateRef + (k1 * (alpha - hold)) + (k2 * (view.AngularSpeed - rateRef)) + (Integral * _integral);
        float off = MathF.Abs(alpha - hold);
        int vcode = off > 0.5f ? 1 : off > 0.3f || MathF.Abs(error) > SlowError * 2f ? Math.Min(pushVCode, 2) : MathF.Abs(error) > SlowError ? Math.Min(pushVCode, 3) : pushVCode;
        return new Decision(vcode, TurnCode.Nearest(rate));
    }

    /// <summary>
    /// The decision taking the fish to <paramref name="goal"/> without a ball (it is not pushing
    /// meanwhile): along the shortest way round the obstacles (<see cref="Waypath"/>) by pursuit of a
    /// point ahead on it. The speed is the fastest gear that can still round the next corner within
    /// the way's margin (its turning radius at 0.28 rad/s cuts the corner by R·(1/cos(φ/2) − 1) ≤
    /// 100 mm for a turn φ), allowing more the farther the corner is (the speed falls by a tenth per
    /// cycle), and whose turning circle reaches the pursued point.
    /// </summary>
    /// <param name="view">The fish as seen.</param>
    /// <param name="me">The fish's estimated pose.</param>
    /// <param name="goal">Where to go.</param>
    /// <param name="around">Walls and obstacles.</param>
    /// <param name="maxVCode">Fastest gear.</param>
    public Decision Travel(in FishView view, in FishTrack me, Vector2 goal, in Surroundings around, int maxVCode = 12)
    {
        _pushing = false;
        _runUp = false;
        around.Ways.Next(me.Position, goal, out Vector2 first, out Vector2 second);
        float look = Math.Clamp(view.Speed * 1.2f, 150f, 350f);
        float toFirst = Vector2.Distance(me.Position, first);
        Vector2 carrot = first;
        if (toFirst < look && first != second)
        {
            // Round the corner: a point on the next leg.
            carrot = first + (Vector2.Normalize(second - first) * MathF.Min(look - toFirst, Vector2.Distance(first, second)));
        }

        Vector2 to = carrot - me.Position;
        float distance = MathF.Max(to.Length(), 1f);
        float eta = Angle.Wrap(MathF.Atan2(to.Y, to.X) - me.Heading);
        float sine = MathF.Abs(eta) >= MathF.PI / 2f ? 1f : MathF.Max(MathF.Sin(MathF.Abs(eta)), 0.05f);
        float fastest = Approach.PlanTurnRate * distance / (2f * sine);
        if (first != second && toFirst > 1f)
        {
            Vector2 inbound = (first - me.Position) / toFirst, outbound = Vector2.Normalize(second - first);
            float half = MathF.Acos(Math.Clamp(Vector2.Dot(inbound, outbound), -1f, 1f)) * 0.5f;
            float cut = (1f / MathF.Max(MathF.Cos(half), 0.05f)) - 1f;
            float corner = cut > 1e-3f ? Approach.PlanTurnRate * 100f / cut : float.PositiveInfinity;
            fastest = MathF.Min(fastest, corner + (0.5f * toFirst));
        }

        int vcode = 1;
        for (int v = Math.Clamp(maxVCode, 1, 14); v >= 1; v--)
        {
            if (SpeedTable.TargetSpeed(v) <= fastest)
            {
                vcode = v;
                break;
            }
        }

        float speed = MathF.Max(view.Speed, SpeedTable.TargetSpeed(vcode));
        float rate = MathF.Abs(eta) > MathF.PI / 2f ? MathF.Sign(eta) * 0.35f : 2f * speed * MathF.Sin(eta) / distance;
        return new Decision(vcode, TurnCode.For(rate, view.AngularSpeed));
    }

    // The push direction nearest the wanted one whose place behind the ball (at `back`, and 150 mm
    // farther for the run-up) keeps the approach's margin from walls and obstacles: a ball in a
    // corner or against a wall is first pushed out along it.
    private static Vector2 Open(Vector2 direction, Vector2 ball, float back, in Surroundings around)
    {
        for (int k = 0; k <= 8; k++)
        {
            float turn = ((k + 1) / 2) * 0.35f * ((k & 1) == 0 ? 1f : -1f);
            float c = MathF.Cos(turn), s = MathF.Sin(turn);
            Vector2 d = new((direction.X * c) - (direction.Y * s), (direction.X * s) + (direction.Y * c));
            if (around.Clearance(ball - (d * back)) >= Approach.WallMargin && around.Clearance(ball - (d * (back + 150f))) >= Approach.WallMargin * 0.8f)
            {
                return d;
            }
        }

        return direction;
    }

    // A contact impulse on a ball near the head tip points from the tip to the ball's centre: put the
    // ball's estimate there (the heading estimate is good to about a degree; the views to ±30 mm).
    private static void Sharpen(in FishTrack me, Vector2 tip, ref BallTrack ball, float radius)
    {
        if (ball.Impulse.LengthSquared() <= 4f)
        {
            return;
        }

        Vector2 normal = Vector2.Normalize(ball.Impulse);
        Vector2 toBall = ball.Position - tip;
        float seen = MathF.Atan2(toBall.Y, toBall.X);
        float felt = MathF.Atan2(normal.Y, normal.X);
        if (toBall.Length() < radius + 40f && MathF.Abs(Angle.Wrap(felt - me.Heading)) < 1f && MathF.Abs(Angle.Wrap(felt - seen)) < 0.8f)
        {
            ball.Contact(tip + (normal * radius), 0.7f);
        }
    }
}
