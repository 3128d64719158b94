namespace URWPGSim2D.Engine.Items.Demo;

/// <summary>
/// How far a ball has come along a route (a polyline of waypoints), and where it should head next:
/// toward a point a fixed distance ahead of its projection on the route (pursuit of a carrot), so a
/// ball off the route is led back onto it and corners are rounded. Progress only moves forward
/// unless the ball ends up far from the route, when it restarts from the nearest leg. One value per
/// ball, kept across cycles.
/// </summary>
internal struct RouteProgress
{
    private const float Lost = 450f;

    /// <summary>Index of the leg the ball is on (from waypoint Leg to Leg + 1).</summary>
    public int Leg;

    /// <summary>The unit direction the ball should go from <paramref name="ball"/>.</summary>
    /// <param name="route">The waypoints, at least two.</param>
    /// <param name="ball">The ball's centre.</param>
    /// <param name="ahead">How far ahead along the route the carrot is, mm.</param>
    public Vector2 Direction(ReadOnlySpan<Vector2> route, Vector2 ball, float ahead)
    {
        int last = route.Length - 2;
        Leg = Math.Clamp(Leg, 0, last);
        if (Distance(route, Leg, ball, out _) > Lost)
        {
            float best = float.PositiveInfinity;
            for (int i = 0; i <= last; i++)
            {
                float d = Distance(route, i, ball, out _);
                if (d < best)
                {
                    best = d;
                    Leg = i;
                }
            }
        }

        // Move on while the ball is past the end of its leg or nearer the next one.
        while (Leg < last)
        {
            float here = Distance(route, Leg, ball, out float t);
            if (t < 1f && here <= Distance(route, Leg + 1, ball, out _))
            {
                break;
            }

            Leg++;
        }

        // The carrot is farther ahead the farther the ball is off the route, so it heads on, not back.
        float off = Distance(route, Leg, ball, out float along);
        Vector2 a = route[Leg], b = route[Leg + 1];
        float left = ahead + off + (Math.Clamp(along, 0f, 1f) * Vector2.Distance(a, b));
        int i2 = Leg;
        while (i2 < last && left > Vector2.Distance(route[i2], route[i2 + 1]))
        {
            left -= Vector2.Distance(route[i2], route[i2 + 1]);
            i2++;
        }

        Vector2 from = route[i2], to = route[i2 + 1];
        float length = Vector2.Distance(from, to);
        Vector2 carrot = length > 1e-3f ? from + ((to - from) * MathF.Min(left / length, 1f)) : to;
        if (i2 == last && left > length)
        {
            // Past the route's end: keep the last leg's direction.
            carrot = to + (Vector2.Normalize(to - from) * (left - length));
        }

        Vector2 way = carrot - ball;
        return way.LengthSquared() > 1f ? Vector2.Normalize(way) : Vector2.Normalize(to - from);
    }

    // Distance from p to leg i, and the parameter t of its nearest point (unclamped along the leg).
    private static float Distance(ReadOnlySpan<Vector2> route, int i, Vector2 p, out float t)
    {
        Vector2 a = route[i], ab = route[i + 1] - a;
        float ll = ab.LengthSquared();
        t = ll > 1e-6f ? Vector2.Dot(p - a, ab) / ll : 0f;
        return Vector2.Distance(p, a + (ab * Math.Clamp(t, 0f, 1f)));
    }
}
