using URWPGSim2D.Collision.Motion;
using URWPGSim2D.Engine.Simulation.Kinematics;
using URWPGSim2D.Strategies;

namespace URWPGSim2D.Engine.Items.Demo;

/// <summary>
/// The steering the demo strategies share: swim to a point (slowing so the turning circle reaches
/// it), push a ball toward a target (get behind it on the target–ball line, then drive through it),
/// and the distance from the head tip. Pure functions of the snapshot; nothing is allocated.
/// </summary>
internal static class Steering
{
    /// <summary>Largest heading error (rad) at which a fish behind a ball counts as lined up.</summary>
    public const float LineUpAngle = 0.5f;

    /// <summary>Unit vector of a heading.</summary>
    public static Vector2 Direction(float heading) => new(MathF.Cos(heading), MathF.Sin(heading));

    /// <summary>The tip of the fish's head.</summary>
    public static Vector2 Head(in FishView me) => me.Position + (Direction(me.Heading) * ((me.BodyLength * 0.5f) + me.HeadLength));

    /// <summary>Heads for <paramref name="aim"/>: the turn code follows the heading error, the speed is the fastest whose turning circle still reaches the point (at most <paramref name="maxVCode"/>).</summary>
    public static Decision SwimTo(in FishView me, Vector2 aim, int maxVCode = 14)
    {
        Vector2 to = aim - me.Position;
        float error = Angle.Wrap(MathF.Atan2(to.Y, to.X) - me.Heading);
        int tcode = 7 + (int)MathF.Round(Math.Clamp(error / 0.4f, -1f, 1f) * 7f);
        float absError = MathF.Abs(error);
        float sine = absError >= MathF.PI / 2f ? 1f : MathF.Max(MathF.Sin(absError), 0.05f);
        float fastest = 0.3f * to.Length() / (2f * sine);
        int vcode = 1;
        for (int v = Math.Clamp(maxVCode, 1, 15); v >= 1; v--)
        {
            if (SpeedTable.TargetSpeed(v) <= fastest)
            {
                vcode = v;
                break;
            }
        }

        return new Decision(vcode, tcode);
    }

    /// <summary>
    /// Pushes a ball toward <paramref name="target"/>: swims to a point <paramref name="standOff"/> mm
    /// behind the ball on the target–ball line, and once lined up (head behind the ball, heading
    /// within <see cref="LineUpAngle"/> of the push direction) drives through the ball at up to
    /// <paramref name="pushVCode"/>.
    /// </summary>
    /// <param name="me">The fish.</param>
    /// <param name="ball">Ball centre.</param>
    /// <param name="radius">Ball radius.</param>
    /// <param name="target">Where the ball should go.</param>
    /// <param name="pushVCode">Fastest gear while driving through the ball.</param>
    /// <param name="standOff">Distance of the point behind the ball, mm.</param>
    /// <param name="approachVCode">Fastest gear on the way behind the ball.</param>
    public static Decision Push(in FishView me, Vector2 ball, float radius, Vector2 target, int pushVCode = 10, float standOff = 90f, int approachVCode = 14)
    {
        Vector2 toTarget = target - ball;
        Vector2 dir = toTarget.LengthSquared() > 1e-6f ? Vector2.Normalize(toTarget) : Direction(me.Heading);
        Vector2 behind = ball - (dir * (radius + standOff));
        Vector2 head = Head(me);
        Vector2 toBall = ball - head;
        float along = Vector2.Dot(toBall, dir);
        float across = MathF.Abs((toBall.X * dir.Y) - (toBall.Y * dir.X));
        float headingError = MathF.Abs(Angle.Wrap(MathF.Atan2(dir.Y, dir.X) - me.Heading));
        bool linedUp = along > -radius * 0.5f && across < radius * 0.8f && headingError < LineUpAngle
            && Vector2.Distance(head, ball) < radius + standOff + 120f;
        if (linedUp)
        {
            return SwimTo(me, ball + (dir * radius), pushVCode);
        }

        // Go round the ball rather than through it: aim beside the ball first when it is between.
        Vector2 aim = behind;
        Vector2 toBehind = behind - me.Position;
        Vector2 toBallCentre = ball - me.Position;
        if (Vector2.Dot(toBallCentre, toBehind) > 0f && toBallCentre.LengthSquared() < toBehind.LengthSquared())
        {
            Vector2 side = new(-dir.Y, dir.X);
            float s = Vector2.Dot(me.Position - ball, side) >= 0f ? 1f : -1f;
            aim = ball + (side * s * (radius + 160f)) - (dir * (radius * 0.5f));
        }

        return SwimTo(me, aim, approachVCode);
    }
}
