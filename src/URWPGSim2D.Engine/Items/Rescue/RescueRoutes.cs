namespace URWPGSim2D.Engine.Items.Rescue;

/// <summary>
/// The ways through the slalom of 急速救援 for the demo (<see cref="RescueDemo"/>). The walls leave
/// a gap |z| &lt; 400 at x = ±550 and pass the centre wall (|z| ≤ 550 at x = 0) on either side. Ball 0
/// starts at the bottom left and comes up through the left gap steeply, so it goes on over the
/// centre wall (its top end) and down through the right gap — the least turning for it; ball 1 is
/// the mirror image (under the centre wall).
/// </summary>
internal static class RescueRoutes
{
    /// <summary>Ball 1 waits until ball 0 is right of this x (past the left gap).</summary>
    public const float ClearX = -150f;

    /// <summary>The defending fish's place: in front of the zone.</summary>
    public static readonly Vector2 Guard = new(1300f, 0f);

    /// <summary>The defending fish clears balls right of this x (past the right gap).</summary>
    public const float GuardX = 600f;

    /// <summary>Where ball 1 waits meanwhile: it is not pushed beyond this x (clear of ball 0's way to the left gap).</summary>
    public const float WaitX = -1000f;

    // Ball 0's route (ball 1's is its mirror in z), a path the pushed ball can follow (it curves at
    // radii of 300 mm and more): a slight turn onto a line at −64° that crosses the left gap, an arc
    // of radius 300 round the centre wall's top end (centre (0, −450), top at z = −750), the mirror
    // line at +64° down through the right gap, a left turn (radius 350) and on into the zone. The
    // ball on it keeps at least 65 mm from every wall (the tests check).
    private static readonly Vector2[] Route0 = Build();

    private static readonly Vector2[] Route1 = Mirror(Route0);

    /// <summary>The route of a ball.</summary>
    public static ReadOnlySpan<Vector2> Route(int ball) => ball == 0 ? Route0 : Route1;

    /// <summary>Where fish k waits once it has nothing to push: the right-hand corner away from the other ball's last legs.</summary>
    public static Vector2 Rest(int k) => new(1300f, k == 0 ? -1150f : 1150f);

    private static Vector2[] Build()
    {
        const float slope = 1.12f;
        const float radius = 300f;
        var centre = new Vector2(0f, -450f);
        Vector2 entry = centre - (radius * new Vector2(MathF.Sin(slope), MathF.Cos(slope)));
        var points = new System.Collections.Generic.List<Vector2> { new(-1350f, 1050f), new(-885f, 650f), entry };
        for (int k = 1; k <= 8; k++)
        {
            // Over the top: the heading turns from −slope to +slope.
            float h = -slope + (2f * slope * k / 8f);
            points.Add(centre - (radius * new Vector2(MathF.Sin(-h), MathF.Cos(h))));
        }

        // Down the mirror line to x = 650, then left round a centre 350 mm to the side, to heading 0.
        Vector2 exit = points[^1];
        Vector2 down = new(MathF.Cos(slope), MathF.Sin(slope));
        Vector2 bend = exit + (down * ((650f - exit.X) / down.X));
        points.Add(bend);
        Vector2 turnCentre = bend + (350f * new Vector2(MathF.Sin(slope), -MathF.Cos(slope)));
        for (int k = 1; k <= 4; k++)
        {
            float h = slope * (1f - (k / 4f));
            points.Add(turnCentre - (350f * new Vector2(MathF.Sin(h), -MathF.Cos(h))));
        }

        points.Add(new Vector2(2100f, 200f));
        return [.. points];
    }

    private static Vector2[] Mirror(Vector2[] route)
    {
        var m = new Vector2[route.Length];
        for (int i = 0; i < route.Length; i++)
        {
            m[i] = new Vector2(route[i].X, -route[i].Y);
        }

        return m;
    }
}
