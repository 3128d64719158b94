using URWPGSim2D.Collision.Motion;
using System.Runtime.InteropServices;
using System.Runtime.Intrinsics;
using System.Runtime.CompilerServices;
using URWPGSim2D.Engine.Simulation.Kinematics;

namespace URWPGSim2D.Engine.Items.Demo;

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

    // The gear on long straight pieces.
    private const int StraightGear = 9;

    // The cheapest paths checked for clearance before the least bad one is taken.
    private const int MaxChecked = 48;

    // The least bad path is taken only when its margin is above this, mm.
    private const float NearlyClear = -50f;

    // Rounding allowance of the skip, mm.
    private const float SkipCushion = 1f;

    // Distance from the body centre to the tail's end (without the caudal fin's tips), mm.
    private const float TailReach = 250f;

    // First-piece samples remembered per gear and turn direction (see Clear).
    private const int Remembered = 8;
    private static readonly int[] Gears = [1, 2, 3, 4, 6, 9];

    // The last choice: lead, gear and word of the path.
    private int _key;

    // The direction of the last choice's first piece (a new path that starts turning the same way is preferred).
    private int _turn;

    /// <summary>
    /// The decision that takes the fish onto the line through <paramref name="goal"/> along
    /// <paramref name="goalHeading"/>, arriving at a point of it up to <paramref name="nearer"/> mm
    /// farther along or <paramref name="farther"/> mm farther back when that is quicker or the only
    /// way clear (counting the rest of the way at <paramref name="arriveVCode"/>). When no path keeps
    /// its margins (by more than 50 mm), the fish heads straight for the goal at a low gear.
    /// </summary>
    /// <param name="view">The fish as seen (for its exact speed and turn rate).</param>
    /// <param name="me">Its estimated pose.</param>
    /// <param name="goal">Where its centre should arrive.</param>
    /// <param name="goalHeading">The heading it should arrive with.</param>
    /// <param name="around">Walls and obstacles.</param>
    /// <param name="avoid">Centre of a disc to keep clear of (the ball to be pushed).</param>
    /// <param name="avoidRadius">Its radius, mm (0: nothing to avoid).</param>
    /// <param name="arriveVCode">Fastest gear in the last 250 mm.</param>
    /// <param name="nearer">How far along the line the arrival point may move, mm.</param>
    /// <param name="farther">How far back the arrival point may move, mm (tried: half of it and all).</param>
    [SkipLocalsInit] // the path buffers are read only where written; zeroing them cost more than planning
    public Decision Toward(in FishView view, in FishTrack me, Vector2 goal, float goalHeading, in Surroundings around, Vector2 avoid, float avoidRadius, int arriveVCode, float nearer = 0f, float farther = 0f)
    {
        const int leads = 4;
        Span<float> offsets = [-nearer, 0f, farther * 0.5f, farther];
        Span<DubinsPath> all = stackalloc DubinsPath[8 * leads * 6];
        Span<int> order = stackalloc int[8 * leads * 6];
        Span<float> costs = stackalloc float[8 * leads * 6];
        Span<int> keys = stackalloc int[8 * leads * 6];
        Span<float> firstPiece = stackalloc float[Gears.Length * 2 * Remembered];
        firstPiece.Fill(float.NaN);
        float reach = (view.BodyLength * 0.5f) + view.HeadLength;
        float arriveSpeed = MathF.Max(SpeedTable.TargetSpeed(arriveVCode), 10f);
        Vector2 back = -new Vector2(MathF.Cos(goalHeading), MathF.Sin(goalHeading));
        Vector2 fromNormal = DubinsPath.Normal(me.Heading), toNormal = DubinsPath.Normal(goalHeading);
        int count = 0;
        for (int l = 0; l < leads; l++)
        {
            if ((l == 0 && nearer <= 0f) || (l >= 2 && farther <= 0f))
            {
                continue;
            }

            float extra = offsets[l];
            Vector2 point = goal + (back * extra);
            for (int g = 0; g < Gears.Length; g++)
            {
                // A gear slower than the fish is now still turns at the radius of its present speed at first.
                float speed = SpeedTable.TargetSpeed(Gears[g]);
                float radius = MathF.Max(speed, view.Speed * 0.8f) / PlanTurnRate;
                int n = DubinsPath.Plan(me.Position, me.Heading, fromNormal, point, goalHeading, toNormal, radius, all[count..]);
                for (int i = count; i < count + n; i++)
                {
                    ref readonly var candidate = ref all[i];
                    int key = (((l * Gears.Length) + g) * 32) + Word(candidate);
                    float cost = Duration(candidate, speed) + (extra / arriveSpeed);
                    costs[i] = key == _key ? cost * 0.85f : candidate.Turn1 != 0 && candidate.Turn1 == _turn ? cost * 0.9f : cost;
                    keys[i] = key;
                    order[i] = i;
                }

                count += n;
            }
        }

        // Cheapest first; the first one clear of walls, obstacles and the disc is taken.
        int chosen = -1, fallback = -1;
        float fallbackClear = float.NegativeInfinity;
        for (int k = 0; k < Math.Min(count, MaxChecked) && chosen < 0; k++)
        {
            int cheapest = k + FirstOfLeast(costs[k..count]);
            (order[k], order[cheapest]) = (order[cheapest], order[k]);
            (costs[k], costs[cheapest]) = (costs[cheapest], costs[k]);
            (keys[k], keys[cheapest]) = (keys[cheapest], keys[k]);
            var margins = firstPiece.Slice(GearOf(keys[k]) * 2 * Remembered, 2 * Remembered);
            float clear = Clear(all[order[k]], around, avoid, avoidRadius, reach, MathF.Max(fallbackClear, NearlyClear), margins);
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

        if (chosen < 0 && fallbackClear > NearlyClear)
        {
            // Nothing keeps the full margins: the least bad, if it is nearly clear.
            chosen = fallback;
        }

        if (chosen < 0)
        {
            _key = -1;
            Vector2 to = goal - me.Position;
            float eta = Angle.Wrap(MathF.Atan2(to.Y, to.X) - me.Heading);
            return new Decision(MathF.Abs(eta) > 1f ? 1 : 2, TurnCode.For(Math.Clamp(eta, -0.35f, 0.35f), view.AngularSpeed));
        }

        var path = all[order[chosen]];
        _key = keys[chosen];
        _turn = path.Turn1;
        int gear = Gears[GearOf(keys[chosen])];
        int vcode = gear;
        bool straight = path.Turn1 == 0 ? path.Length1 > Braking(view.Speed) : path.Length1 < 20f && path.Turn2 == 0 && path.Length2 > Braking(view.Speed);
        if (straight)
        {
            // On a straight piece with room to slow down for the next turn: faster.
            vcode = Math.Max(gear, StraightGear);
        }

        vcode = path.Length < 250f ? Math.Min(vcode, arriveVCode) : vcode;
        return Follow(view, me, path, SpeedTable.TargetSpeed(gear), vcode);
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

        float rate = Angle.Wrap(turned) / ahead;
        return new Decision(vcode, TurnCode.For(rate, view.AngularSpeed));
    }

    // The path's smallest margin: clearance to walls and obstacles beyond WallMargin (head tip: 25 mm)
    // and to the avoided disc (centre: 100 mm, tip: 20 mm, the tail's middle and end: 60 mm — the
    // tail swings while the fish turns), over samples past its first 80 mm. Only the sign of a clear
    // path's margin is used, so samples that cannot go below zero are skipped: per mm of path the
    // centre moves 1 mm and a point an arm away up to 1 + arm ÷ radius mm, and a clearance changes at
    // most ObstacleField.MaxSlope mm per mm moved (a distance 1 mm). A path that is not clear gets its
    // exact margin unless that falls below giveUp: the path cannot be chosen then, and the scan stops.
    // Every candidate of one gear starts at the fish with the same radius, so those whose first turn
    // goes the same way share their first piece: its samples' margins (80, 120, ... mm along) are
    // kept in firstPiece (NaN: not yet measured; the turn's two directions one after the other) and
    // measured once a plan. A path that starts straight (none of Plan's does) keeps nothing.
    private static float Clear(in DubinsPath path, in Surroundings around, Vector2 avoid, float avoidRadius, float reach, float giveUp, Span<float> firstPiece)
    {
        float fall = ObstacleField.MaxSlope * (1f + (MathF.Max(reach, TailReach) / path.Radius));
        float worst = float.PositiveInfinity;
        float length = path.Length;
        float skipTo = float.NegativeInfinity;
        // The later pieces are worked out only when a sample reaches them (most scans stop early).
        var pieces = path.WalkFirst();
        bool walked = false;
        var remembered = firstPiece.Slice(path.Turn1 > 0 ? Remembered : 0, Remembered);
        int k = 0;
        for (float s = MathF.Min(80f, length); s <= length + 0.01f; s += Sample, k++)
        {
            if (s <= skipTo)
            {
                continue;
            }

            // The first piece's k-th sample when the samples start at 80 mm.
            bool shared = k < Remembered && length >= 80f && path.Turn1 != 0 && s - path.Length1 <= 0f;
            float margin = shared ? remembered[k] : float.NaN;
            if (float.IsNaN(margin))
            {
                if (!walked && s - path.Length1 > 0f)
                {
                    pieces = path.Walk();
                    walked = true;
                }

                margin = Margin(path, pieces, s, around, avoid, avoidRadius, reach);
                if (shared)
                {
                    remembered[k] = margin;
                }
            }

            worst = MathF.Min(worst, margin);
            if (worst < giveUp)
            {
                break;
            }

            if (margin > SkipCushion)
            {
                skipTo = s + ((margin - SkipCushion) / fall);
            }
        }

        return worst;
    }

    /// <summary>
    /// The index of the first of the smallest of <paramref name="values"/> (not NaN, at least one):
    /// what a scan keeping the first strictly smaller value finds, the least found eight at a time.
    /// </summary>
    internal static int FirstOfLeast(ReadOnlySpan<float> values)
    {
        int width = Vector256<float>.Count;
        if (!Vector256.IsHardwareAccelerated || values.Length < 2 * width)
        {
            int first = 0;
            for (int j = 1; j < values.Length; j++)
            {
                first = values[j] < values[first] ? j : first;
            }

            return first;
        }

        // The least, eight lanes at a time (the last load overlaps the one before it).
        ref float start = ref MemoryMarshal.GetReference(values);
        nuint last = (nuint)(values.Length - width);
        var lanes = Vector256.LoadUnsafe(ref start);
        for (nuint i = (nuint)width; i < last; i += (nuint)width)
        {
            lanes = Vector256.Min(lanes, Vector256.LoadUnsafe(ref start, i));
        }

        lanes = Vector256.Min(lanes, Vector256.LoadUnsafe(ref start, last));
        float least = lanes[0];
        for (int lane = 1; lane < width; lane++)
        {
            least = lanes[lane] < least ? lanes[lane] : least;
        }

        // Then the first lane equal to it (−0 equals +0, as for the scan).
        var wanted = Vector256.Create(least);
        for (nuint i = 0; ; i = i + (nuint)width > last ? last : i + (nuint)width)
        {
            uint hits = Vector256.Equals(Vector256.LoadUnsafe(ref start, i), wanted).ExtractMostSignificantBits();
            if (hits != 0)
            {
                return (int)i + BitOperations.TrailingZeroCount(hits);
            }

            if (i == last)
            {
                return 0; // only for a NaN, which a cost never is
            }
        }
    }

    // The smallest margin of the fish's pose s mm along the path (see Clear).
    private static float Margin(in DubinsPath path, in DubinsPath.Pieces pieces, float s, in Surroundings around, Vector2 avoid, float avoidRadius, float reach)
    {
        var (p, ahead) = path.Facing(s, pieces);
        Vector2 tip = p + (ahead * reach);
        float margin = MathF.Min(around.Clearance(p) - WallMargin, around.Clearance(tip) - 25f);
        if (avoidRadius > 0f)
        {
            Vector2 tail = p - (ahead * TailReach);
            margin = MathF.Min(margin, Vector2.Distance(p, avoid) - avoidRadius - 100f);
            margin = MathF.Min(margin, Vector2.Distance(tip, avoid) - avoidRadius - 20f);
            margin = MathF.Min(margin, Vector2.Distance((p + tail) * 0.5f, avoid) - avoidRadius - 60f);
            margin = MathF.Min(margin, Vector2.Distance(tail, avoid) - avoidRadius - 60f);
        }

        return margin;
    }

    // The time a path takes: turns at the plan's rate, straight pieces at the straight gear when they
    // are long enough to get up to it and slow down again (else at the turns' speed).
    private static float Duration(in DubinsPath p, float turnSpeed)
    {
        float straight = (p.Turn1 == 0 ? p.Length1 : 0f) + (p.Turn2 == 0 ? p.Length2 : 0f) + (p.Turn3 == 0 ? p.Length3 : 0f);
        float fast = SpeedTable.TargetSpeed(StraightGear);
        float straightTime = straight > 2f * Braking(fast) ? (straight / fast) + 1.5f : straight / turnSpeed;
        return (p.Turning / PlanTurnRate) + straightTime;
    }

    // About how far a fish at speed v goes before it has slowed to a turning speed (a tenth less per cycle: ~1.5 s).
    private static float Braking(float speed) => speed * 1.0f;

    // The index in Gears of a candidate's key ((lead × gears + gear) × 32 + word).
    private static int GearOf(int key) => (key / 32) % Gears.Length;

    private static int Word(in DubinsPath p) => ((p.Turn1 + 1) * 9) + ((p.Turn2 + 1) * 3) + (p.Turn3 + 1);
}
