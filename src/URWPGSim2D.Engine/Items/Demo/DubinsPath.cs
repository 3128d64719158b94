using URWPGSim2D.Collision.Motion;

namespace URWPGSim2D.Engine.Items.Demo;

/// <summary>
/// One of the shortest ways for a body that turns no tighter than a radius to go from one pose to
/// another (L. E. Dubins, 1957): three pieces, each a turn at the radius (+1 toward +ω, i.e. from
/// +X toward +Z; −1 the other way) or straight (0), of the given lengths (mm). <see cref="Plan(Vector2, float, Vector2, float, float, Span{DubinsPath})"/>
/// gives the candidates (turn-straight-turn four ways, turn-turn-turn two ways with the middle circle on
/// either side).
/// </summary>
internal readonly struct DubinsPath
{
    /// <summary>A path from its pieces.</summary>
    public DubinsPath(Vector2 start, float heading, float radius, int turn1, float length1, int turn2, float length2, int turn3, float length3)
    {
        Start = start;
        Heading = heading;
        Radius = radius;
        Turn1 = (sbyte)turn1;
        Turn2 = (sbyte)turn2;
        Turn3 = (sbyte)turn3;
        Length1 = length1;
        Length2 = length2;
        Length3 = length3;
    }

    /// <summary>Start position, mm.</summary>
    public Vector2 Start { get; }

    /// <summary>Start heading, rad.</summary>
    public float Heading { get; }

    /// <summary>Turning radius, mm.</summary>
    public float Radius { get; }

    /// <summary>Direction of the first piece (+1, −1 or 0 for straight).</summary>
    public sbyte Turn1 { get; }

    /// <summary>Direction of the second piece.</summary>
    public sbyte Turn2 { get; }

    /// <summary>Direction of the third piece.</summary>
    public sbyte Turn3 { get; }

    /// <summary>Length of the first piece, mm.</summary>
    public float Length1 { get; }

    /// <summary>Length of the second piece, mm.</summary>
    public float Length2 { get; }

    /// <summary>Length of the third piece, mm.</summary>
    public float Length3 { get; }

    /// <summary>Whole length, mm.</summary>
    public float Length => Length1 + Length2 + Length3;

    /// <summary>Total turning, rad.</summary>
    public float Turning => ((Turn1 != 0 ? Length1 : 0f) + (Turn2 != 0 ? Length2 : 0f) + (Turn3 != 0 ? Length3 : 0f)) / Radius;

    /// <summary>The pose at distance <paramref name="s"/> along the path (clamped to its ends).</summary>
    public (Vector2 Position, float Heading) At(float s) => At(s, Walk());

    /// <summary>
    /// Where each piece begins, with what a step along it needs (its direction when straight, its
    /// turning centre when turning), for asking many poses of one path.
    /// </summary>
    public Pieces Walk()
    {
        var first = Piece.From(Start, Heading, Turn1, Radius);
        var second = Piece.From(first.Along(Turn1, Length1, Radius), Turn2, Radius);
        var third = Piece.From(second.Along(Turn2, Length2, Radius), Turn3, Radius);
        return new Pieces(first, second, third);
    }

    /// <summary>
    /// <see cref="Walk"/>'s first piece alone (the other two default): enough for the poses up to
    /// <see cref="Length1"/> along the path.
    /// </summary>
    public Pieces WalkFirst() => new(Piece.From(Start, Heading, Turn1, Radius), default, default);

    /// <summary>
    /// The pose at distance <paramref name="s"/> along the path (clamped to its ends), stepping from
    /// the start of its piece (<paramref name="pieces"/>, from <see cref="Walk"/>).
    /// </summary>
    public (Vector2 Position, float Heading) At(float s, in Pieces pieces)
    {
        Piece piece = Locate(s, pieces, out int turn, out float along);
        return piece.Along(turn, along, Radius);
    }

    /// <summary>
    /// The position at distance <paramref name="s"/> along the path and the unit vector of its
    /// heading there: <see cref="At(float, in Pieces)"/> with the heading's cosine and sine, which a
    /// straight piece already holds (its <see cref="Piece.Lever"/>, the same bits).
    /// </summary>
    public (Vector2 Position, Vector2 Ahead) Facing(float s, in Pieces pieces)
    {
        Piece piece = Locate(s, pieces, out int turn, out float along);
        var (position, heading) = piece.Along(turn, along, Radius);
        return (position, turn == 0 ? piece.Lever : new Vector2(MathF.Cos(heading), MathF.Sin(heading)));
    }

    // The piece that distance s along the path (clamped to its ends) falls on, its turn and how far
    // along it s lies.
    private Piece Locate(float s, in Pieces pieces, out int turn, out float along)
    {
        s = Math.Clamp(s, 0f, Length);
        float rest = s - Length1;
        if (rest <= 0f)
        {
            (turn, along) = (Turn1, MathF.Min(s, Length1));
            return pieces.First;
        }

        if (rest - Length2 <= 0f)
        {
            (turn, along) = (Turn2, MathF.Min(rest, Length2));
            return pieces.Second;
        }

        (turn, along) = (Turn3, MathF.Min(rest - Length2, Length3));
        return pieces.Third;
    }

    /// <summary>
    /// Fills <paramref name="paths"/> (room for 8) with the candidate paths from (<paramref name="from"/>,
    /// <paramref name="fromHeading"/>) to (<paramref name="to"/>, <paramref name="toHeading"/>) at turning
    /// radius <paramref name="radius"/>; returns how many exist.
    /// </summary>
    public static int Plan(Vector2 from, float fromHeading, Vector2 to, float toHeading, float radius, Span<DubinsPath> paths) =>
        Plan(from, fromHeading, Normal(fromHeading), to, toHeading, Normal(toHeading), radius, paths);

    /// <summary>
    /// <see cref="Plan(Vector2, float, Vector2, float, float, Span{DubinsPath})"/> with the headings'
    /// normals given (<see cref="Normal"/>), for planning many radii or goals from the same headings.
    /// </summary>
    public static int Plan(Vector2 from, float fromHeading, Vector2 fromNormal, Vector2 to, float toHeading, Vector2 toNormal, float radius, Span<DubinsPath> paths)
    {
        int n = 0;
        for (int a = -1; a <= 1; a += 2)
        {
            Vector2 startCentre = from + (a * radius * fromNormal);
            for (int b = -1; b <= 1; b += 2)
            {
                if (TurnStraightTurn(from, fromHeading, startCentre, toHeading, to + (b * radius * toNormal), radius, a, b, out var path))
                {
                    paths[n++] = path;
                }
            }

            Vector2 endCentre = to + (a * radius * toNormal);
            for (int side = -1; side <= 1; side += 2)
            {
                if (TurnTurnTurn(from, fromHeading, startCentre, toHeading, endCentre, radius, a, side, out var ccc))
                {
                    paths[n++] = ccc;
                }
            }
        }

        return n;
    }

    /// <summary>The unit vector a quarter turn toward +ω from <paramref name="heading"/>: a +1 turn's centre lies that way.</summary>
    public static Vector2 Normal(float heading) => new(-MathF.Sin(heading), MathF.Cos(heading));

    // The centre of the turning circle of direction t at a pose.
    private static Vector2 Centre(Vector2 p, float h, float r, int t) => p + (t * r * Normal(h));

    // The heading of travel at a point of the circle (centre c) turning in direction t.
    private static float TangentHeading(Vector2 point, Vector2 c, int t)
    {
        Vector2 out_ = point - c;
        return MathF.Atan2(out_.Y, out_.X) + (t * MathF.PI * 0.5f);
    }

    // Turning from heading h1 to h2 in direction t, in [0, 2π).
    private static float Sweep(float h1, float h2, int t)
    {
        float d = t * (h2 - h1);
        if (d <= -2f * MathF.PI || d >= 2f * MathF.PI)
        {
            // (a smaller sweep is its own remainder)
            d %= 2f * MathF.PI;
        }

        return d < 0f ? d + (2f * MathF.PI) : d;
    }

    private static bool TurnStraightTurn(Vector2 p0, float h0, Vector2 c1, float h1, Vector2 c2, float r, int t1, int t2, out DubinsPath path)
    {
        Vector2 w = c2 - c1;
        float d = w.Length();
        float heading, straight;
        if (t1 == t2)
        {
            // Outer tangent: parallel to the line of centres.
            straight = d;
            heading = MathF.Atan2(w.Y, w.X);
        }
        else
        {
            // Inner tangent: crosses between the circles.
            if (d < 2f * r)
            {
                path = default;
                return false;
            }

            straight = MathF.Sqrt((d * d) - (4f * r * r));
            heading = MathF.Atan2(w.Y, w.X) + (t1 * MathF.Atan2(2f * r, straight));
        }

        path = new DubinsPath(p0, h0, r, t1, Sweep(h0, heading, t1) * r, 0, straight, t2, Sweep(heading, h1, t2) * r);
        return true;
    }

    private static bool TurnTurnTurn(Vector2 p0, float h0, Vector2 c1, float h1, Vector2 c2, float r, int t, int place, out DubinsPath path)
    {
        Vector2 w = c2 - c1;
        float d = w.Length();
        if (d > 4f * r || d < 1e-3f)
        {
            path = default;
            return false;
        }

        // The middle circle touches both, on either side of the line of centres.
        float h = MathF.Sqrt((4f * r * r) - (d * d * 0.25f));
        Vector2 side = new Vector2(-w.Y, w.X) / d;
        Vector2 c3 = ((c1 + c2) * 0.5f) + (place * h * side);
        float a1 = TangentHeading((c1 + c3) * 0.5f, c1, t);
        float a2 = TangentHeading((c3 + c2) * 0.5f, c2, t);
        path = new DubinsPath(p0, h0, r, t, Sweep(h0, a1, t) * r, -t, Sweep(a1, a2, -t) * r, t, Sweep(a2, h1, t) * r);
        return true;
    }

    /// <summary>The three pieces of a path, each from its start (<see cref="Walk"/>).</summary>
    /// <param name="First">The first piece.</param>
    /// <param name="Second">The second piece.</param>
    /// <param name="Third">The third piece.</param>
    public readonly record struct Pieces(Piece First, Piece Second, Piece Third);

    /// <summary>A piece's start pose and the direction it goes (straight) or the centre it turns about.</summary>
    /// <param name="Position">Start position, mm.</param>
    /// <param name="Heading">Start heading, rad.</param>
    /// <param name="Lever">The unit direction of travel when straight; the turning centre when turning.</param>
    public readonly record struct Piece(Vector2 Position, float Heading, Vector2 Lever)
    {
        /// <summary>A piece starting at a pose, turning in direction <paramref name="turn"/> at <paramref name="radius"/>.</summary>
        public static Piece From(Vector2 position, float heading, int turn, float radius) =>
            new(position, heading, turn == 0 ? new Vector2(MathF.Cos(heading), MathF.Sin(heading)) : Centre(position, heading, radius, turn));

        /// <summary>A piece starting at a pose.</summary>
        public static Piece From((Vector2 Position, float Heading) pose, int turn, float radius) => From(pose.Position, pose.Heading, turn, radius);

        /// <summary>The pose <paramref name="length"/> mm along the piece (itself for 0 or less).</summary>
        public (Vector2 Position, float Heading) Along(int turn, float length, float radius)
        {
            if (length <= 0f)
            {
                return (Position, Heading);
            }

            if (turn == 0)
            {
                return (Position + (Lever * length), Heading);
            }

            float swept = turn * length / radius;
            float cos = MathF.Cos(swept), sin = MathF.Sin(swept);
            Vector2 r = Position - Lever;
            return (Lever + new Vector2((r.X * cos) - (r.Y * sin), (r.X * sin) + (r.Y * cos)), Angle.Wrap(Heading + swept));
        }
    }
}
