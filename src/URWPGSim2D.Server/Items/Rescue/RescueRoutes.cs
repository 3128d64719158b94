using System;
using System.Numerics;

namespace URWPGSim2D.Server.Items.Rescue;

/// <summary>
/// The ways through the slalom of 急速救援 for the demo (<see cref="RescueDemo"/>). The walls leave
/// a gap |z| &lt; 400 at x = ±550 and pass the centre wall (|z| ≤ 550 at x = 0) on either side. Ball 0
/// starts at the bottom left and comes up into the left gap at about −50°, so it goes on over the
/// centre wall (its top end) and down through the right gap — the least turning for it; ball 1 is
/// the mirror image (under the centre wall).
/// </summary>
internal static class RescueRoutes
{
    /// <summary>Ball 1 waits until ball 0 is right of this x (past the left gap).</summary>
    public const float ClearX = -150f;

    /// <summary>Where ball 1 waits meanwhile: it is not pushed beyond this x (clear of ball 0's way to the left gap).</summary>
    public const float WaitX = -1000f;

    // Ball 0's route (ball 1's is its mirror in z): from the start, into the left gap, over the
    // centre wall's top end with 300 mm to spare, down through the right gap, into the zone.
    private static readonly Vector2[] Route0 =
    [
        new(-1350f, 1050f), new(-850f, 300f), new(-550f, 0f), new(-250f, -550f), new(0f, -850f),
        new(250f, -550f), new(550f, 0f), new(950f, 150f), new(2100f, 0f),
    ];

    private static readonly Vector2[] Route1 = Mirror(Route0);

    /// <summary>The route of a ball.</summary>
    public static ReadOnlySpan<Vector2> Route(int ball) => ball == 0 ? Route0 : Route1;

    /// <summary>Where fish k waits once it has nothing to push: the right-hand corner away from the other ball's last legs.</summary>
    public static Vector2 Rest(int k) => new(1300f, k == 0 ? -1150f : 1150f);

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
