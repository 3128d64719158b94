using URWPGSim2D.Collision.Motion;
using URWPGSim2D.Engine.Simulation.Kinematics;

namespace URWPGSim2D.Engine.Items.Demo;

/// <summary>
/// Pushing a ball to a point with a fish that turns slowly (at most about 0.4 rad/s), by pursuit
/// of a point on the push line (the line through the ball toward the target). A fish behind the
/// ball and roughly facing along the line follows it with its head (heading along the line,
/// turned toward it in proportion to the head's offset) and drives through the ball; it keeps
/// doing so, with wider tolerances, until it loses the line (the observation noise would
/// otherwise make it flip between modes). Any other fish first swims to a staging point far
/// enough behind the ball on the line to finish its turn there (round the ball when the ball is in
/// the way). The line is taken afresh from the ball every cycle, so a ball that drifts sideways is
/// followed. One value per fish, kept by the strategy across cycles.
/// </summary>
internal struct Dribble
{
    private bool _onLine;

    /// <summary>Largest heading error (rad) at which the fish drives through the ball.</summary>
    public const float LineUp = 0.45f;

    /// <summary>Distance of the staging point behind the ball's back, mm.</summary>
    public const float Staging = 380f;

    /// <summary>The decision pushing <paramref name="ball"/> (radius <paramref name="radius"/>) toward <paramref name="target"/>.</summary>
    /// <param name="me">The fish.</param>
    /// <param name="ball">Ball centre.</param>
    /// <param name="radius">Ball radius.</param>
    /// <param name="target">Where the ball should go.</param>
    /// <param name="pushVCode">Speed gear while pushing.</param>
    /// <param name="field">Field length and width, to keep the staging point 200 mm off the walls (none when zero).</param>
    public Decision Toward(in FishView me, Vector2 ball, float radius, Vector2 target, int pushVCode = 5, Vector2 field = default)
    {
        Vector2 toTarget = target - ball;
        float distance = toTarget.Length();
        Vector2 dir = distance > 1e-3f ? toTarget / distance : Steering.Direction(me.Heading);
        Vector2 normal = new(-dir.Y, dir.X);
        Vector2 rel = me.Position - ball;
        float along = Vector2.Dot(rel, dir);
        float aside = Vector2.Dot(rel, normal);
        float reach = (me.BodyLength * 0.5f) + me.HeadLength + radius;
        float error = MathF.Abs(Angle.Wrap(MathF.Atan2(dir.Y, dir.X) - me.Heading));
        Vector2 head = Steering.Head(me) - ball;
        float headAlong = Vector2.Dot(head, dir);
        float headAside = Vector2.Dot(head, normal);
        bool onLine = _onLine
            ? headAlong < radius * 0.5f && headAlong > -(radius + 700f) && MathF.Abs(headAside) < MathF.Max(2f * radius, -headAlong * 0.8f) && error < 1.6f
            : headAlong < -radius * 0.2f && headAlong > -(radius + 600f) && MathF.Abs(headAside) < MathF.Max(radius, -headAlong * 0.6f) && error < 1.3f;
        _onLine = onLine;
        if (onLine)
        {
            // Follow the push line with the head (a Stanley-type line follower): heading along the
            // line, turned toward it in proportion to the head's offset.
            float desired = MathF.Atan2(dir.Y, dir.X) - MathF.Atan(headAside / 120f);
            float turn = Angle.Wrap(desired - me.Heading);
            int tcode = 7 + (int)MathF.Round(Math.Clamp(turn / 0.6f, -1f, 1f) * 7f);
            int v = MathF.Abs(turn) > 0.6f ? 3 : headAlong > -(radius + 150f) ? (distance < 200f ? Math.Min(pushVCode, 5) : pushVCode) : 6;
            return new Decision(v, tcode);
        }

        Vector2 stage = ball - (dir * (reach + Staging));
        if (field != default)
        {
            // Keep the staging point off the walls (the fish cannot turn there).
            Vector2 room = (field * 0.5f) - new Vector2(200f);
            stage = Vector2.Clamp(stage, -room, room);
        }

        if (Vector2.Distance(me.Position, stage) < 130f)
        {
            // At the staging point: turn toward the ball nearly on the spot.
            return Swim(me, ball, 3);
        }

        Vector2 toStage = stage - me.Position;
        Vector2 toBall = ball - me.Position;
        float t = toStage.LengthSquared() > 1f ? Math.Clamp(Vector2.Dot(toBall, toStage) / toStage.LengthSquared(), 0f, 1f) : 0f;
        if (Vector2.Distance(me.Position + (toStage * t), ball) < reach + 60f && t > 0f && t < 1f)
        {
            // The ball lies across the way to the staging point: pass it on the fish's side.
            float s = aside >= 0f ? 1f : -1f;
            return Swim(me, ball + (normal * s * (reach + 160f)) - (dir * reach), 9);
        }
        return Swim(me, stage, 10);
    }

    /// <summary>
    /// Heads for a point: a proportional turn code (full turn beyond 0.8 rad of error, so the slow
    /// turn response does not overshoot), and the fastest speed whose turning circle still reaches
    /// the point, at least VCode 2 so the fish always turns, at most <paramref name="maxVCode"/>.
    /// </summary>
    public static Decision Swim(in FishView me, Vector2 aim, int maxVCode)
    {
        Vector2 to = aim - me.Position;
        float error = Angle.Wrap(MathF.Atan2(to.Y, to.X) - me.Heading);
        int tcode = 7 + (int)MathF.Round(Math.Clamp(error / 0.8f, -1f, 1f) * 7f);
        float absError = MathF.Abs(error);
        float sine = absError >= MathF.PI / 2f ? 1f : MathF.Max(MathF.Sin(absError), 0.05f);
        float fastest = 0.35f * to.Length() / (2f * sine);
        if (absError > 0.6f && to.Length() < 400f)
        {
            // Close and facing away: turn nearly on the spot instead of orbiting the point.
            return new Decision(1, error < 0f ? 0 : 14);
        }

        int vcode = 2;
        for (int v = Math.Clamp(maxVCode, 2, 15); v >= 2; v--)
        {
            if (SpeedTable.TargetSpeed(v) <= fastest)
            {
                vcode = v;
                break;
            }
        }

        return new Decision(vcode, tcode);
    }
}
