using System;
using System.Numerics;
using URWPGSim2D.Server.Simulation.Kinematics;

namespace URWPGSim2D.Server.Items.Demo;

/// <summary>
/// Brings a fish to a pose (a point and a heading) the way a slow-turning body must: every cycle it
/// plans the shortest turn-limited paths (<see cref="DubinsPath"/>) from the fish's estimated pose at
/// several speeds — each speed turns at its own radius, speed ÷ 0.28 rad/s, so a slow fish turns
/// tightly — drops the paths that pass too close to a wall, an obstacle or the disc to avoid (the ball
/// to be pushed), and follows the quickest one left by pursuit of a point a little ahead on it. The
/// turn code anticipates the turn rate's lag (it approaches its gear's value by a tenth per cycle).
/// One value per fish, kept across cycles (it remembers its last choice, to hold it unless another is
/// clearly quicker).
/// </summary>
internal struct Approach
{
    /// <summary>Turn rate the plans assume, rad/s (below the table's 0.349 so the fish can catch up).</summary>
    public const float PlanTurnRate = 0.28f;

    /// <summary>Clearance kept between the fish's centre and a wall or obstacle, mm.</summary>
    public const float WallMargin = 100f;

    private const float Sample = 40f;

    // Distance from the body centre to the tail's end (without the caudal fin's tips), mm.
    private const float TailReach = 250f;
    private static readonly int[] Gears = [1, 2, 3, 4, 6, 9];

    // The last choice: lead, gear and word of the path.
    private int _key;

    // The direction of the last choice's first piece (a new path that starts turning the same way is preferred).
    private int _turn;

    /// <summary>
    /// The decision that takes the fish onto the line through <paramref name="goal"/> along
    /// <paramref name="goalHeading"/>, arriving at a point of it up to <paramref name="extraLeads"/> mm
    /// farther back when that is quicker (counting the rest of the way at <paramref name="arriveVCode"/>).
    /// </summary>
    /// <param name="view">The fish as seen (for its exact speed and turn rate).</param>
    /// <param name="me">Its estimated pose.</param>
    /// <param name="goal">Where its centre should arrive.</param>
    /// <param name="goalHeading">The heading it should arrive with.</param>
    /// <param name="around">Walls and obstacles.</param>
    /// <param name="avoid">Centre of a disc to keep clear of (the ball to be pushed).</param>
    /// <param name="avoidRadius">Its radius, mm (0: nothing to avoid).</param>
    /// <param name="arriveVCode">Fastest gear in the last 250 mm.</param>
    /// <param name="extraLeads">How far back the arrival point may move, mm (tried: 0, a third, all of it).</param>
    public Decision Toward(in FishView view, in FishTrack me, Vector2 goal, float goalHeading, in Surroundings around, Vector2 avoid, float avoidRadius, int arriveVCode, float extraLeads = 0f)
    {
        const int leads = 3;
        Span<DubinsPath> paths = stackalloc DubinsPath[8];
        Span<DubinsPath> all = stackalloc DubinsPath[8 * leads * 6];
        Span<float> costs = stackalloc float[8 * leads * 6];
        Span<int> keys = stackalloc int[8 * leads * 6];
        float reach = (view.BodyLength * 0.5f) + view.HeadLength;
        float arriveSpeed = MathF.Max(SpeedTable.TargetSpeed(arriveVCode), 10f);
        Vector2 back = -new Vector2(MathF.Cos(goalHeading), MathF.Sin(goalHeading));
        int count = 0;
        for (int l = 0; l < (extraLeads > 0f ? leads : 1); l++)
        {
            float extra = extraLeads * l / (leads - 1);
            Vector2 point = goal + (back * extra);
            for (int g = 0; g < Gears.Length; g++)
            {
                float speed = SpeedTable.TargetSpeed(Gears[g]);
                int n = DubinsPath.Plan(me.Position, me.Heading, point, goalHeading, speed / PlanTurnRate, paths);
                for (int i = 0; i < n; i++)
                {
                    int key = (((l * Gears.Length) + g) * 32) + Word(paths[i]);
                    float cost = (paths[i].Length / speed) + (extra / arriveSpeed);
                    all[count] = paths[i];
                    costs[count] = key == _key ? cost * 0.85f : paths[i].Turn1 != 0 && paths[i].Turn1 == _turn ? cost * 0.9f : cost;
                    keys[count] = key;
                    count++;
                }
            }
        }

        // Cheapest first; the first one clear of walls, obstacles and the disc is taken.
        int chosen = -1, fallback = -1;
        float fallbackClear = float.NegativeInfinity;
        for (int k = 0; k < count && chosen < 0; k++)
        {
            int cheapest = k;
            for (int j = k + 1; j < count; j++)
            {
                if (costs[j] < costs[cheapest])
                {
                    cheapest = j;
                }
            }

            (all[k], all[cheapest]) = (all[cheapest], all[k]);
            (costs[k], costs[cheapest]) = (costs[cheapest], costs[k]);
            (keys[k], keys[cheapest]) = (keys[cheapest], keys[k]);
            float clear = Clear(all[k], around, avoid, avoidRadius, reach);
            if (clear >= 0f)
            {
                chosen = k;
            }
            else if (clear > fallbackClear)
            {
                fallback = k;
                fallbackClear = clear;
            }
        }

        chosen = chosen >= 0 ? chosen : fallback;
        _key = keys[chosen];
        _turn = all[chosen].Turn1;
        int gear = Gears[(keys[chosen] / 32) % Gears.Length];
        int vcode = all[chosen].Length < 250f ? Math.Min(gear, arriveVCode) : gear;
        return Follow(view, me, all[chosen], SpeedTable.TargetSpeed(gear), vcode);
    }

    /// <summary>
    /// The decision following <paramref name="path"/> (which starts at the fish) at gear
    /// <paramref name="vcode"/>: the turn rate is the path's heading change over the next 0.7 s of
    /// travel divided by 0.7 s (the rate lags, so it looks a little ahead), sent through <see cref="TurnCode"/>.
    /// </summary>
    public static Decision Follow(in FishView view, in FishTrack me, in DubinsPath path, float planSpeed, int vcode)
    {
        const float ahead = 0.7f;
        float speed = MathF.Max(view.Speed, planSpeed);
        float s = speed * ahead;
        float turned = path.At(s).Heading - path.Heading;
        if (s > path.Length)
        {
            turned = path.At(path.Length).Heading - path.Heading;
        }

        float rate = Steering.Wrap(turned) / ahead;
        return new Decision(vcode, TurnCode.For(rate, view.AngularSpeed));
    }

    // The path's smallest margin: clearance to walls and obstacles beyond WallMargin (head tip: 25 mm)
    // and to the avoided disc (centre: 100 mm, tip: 20 mm, the tail's middle and end: 60 mm — the
    // tail swings while the fish turns), over samples past its first 80 mm.
    private static float Clear(in DubinsPath path, in Surroundings around, Vector2 avoid, float avoidRadius, float reach)
    {
        float worst = float.PositiveInfinity;
        float length = path.Length;
        for (float s = MathF.Min(80f, length); s <= length + 0.01f; s += Sample)
        {
            var (p, h) = path.At(s);
            Vector2 tip = p + (new Vector2(MathF.Cos(h), MathF.Sin(h)) * reach);
            worst = MathF.Min(worst, around.Clearance(p) - WallMargin);
            worst = MathF.Min(worst, around.Clearance(tip) - 25f);
            if (avoidRadius > 0f)
            {
                Vector2 tail = p - (new Vector2(MathF.Cos(h), MathF.Sin(h)) * TailReach);
                worst = MathF.Min(worst, Vector2.Distance(p, avoid) - avoidRadius - 100f);
                worst = MathF.Min(worst, Vector2.Distance(tip, avoid) - avoidRadius - 20f);
                worst = MathF.Min(worst, Vector2.Distance((p + tail) * 0.5f, avoid) - avoidRadius - 60f);
                worst = MathF.Min(worst, Vector2.Distance(tail, avoid) - avoidRadius - 60f);
            }

            if (worst < -1000f)
            {
                break;
            }
        }

        return worst;
    }

    private static int Word(in DubinsPath p) => ((p.Turn1 + 1) * 9) + ((p.Turn2 + 1) * 3) + (p.Turn3 + 1);
}
