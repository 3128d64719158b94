using System.Globalization;
using URWPGSim2D.Collision.Motion;
using URWPGSim2D.Engine.Items.Demo;
using static URWPGSim2D.Engine.Items.BallGrab.BallGrabLayout;

namespace URWPGSim2D.Engine.Items.BallGrab;

/// <summary>
/// The demo strategy of 抢球博弈. Each fish takes the ball its team has not scored yet that is best
/// worth the trip (value over distance, the two fish on different balls) and pushes it with
/// <see cref="Pusher"/> along a route into the team's box. A box opens only toward its end wall, so
/// the route goes past the end of the bar on the ball's side, round it into the channel between the
/// box and the wall, down the channel to beside the opening and from there diagonally into the box
/// (a ball stopped against the box's back wall lies wholly inside). The route starts at the ball and
/// is made afresh every cycle from where the ball is; the ball heads for a point 300 mm ahead on it
/// (<see cref="RouteProgress"/>), at gear 6, gear 4 once beside the box. A fish on one ball for 60 s
/// leaves it alone for as long and takes another; a ball against an end wall (no fish gets behind
/// it there) is taken last. A fish caught inside a box first swims out through the opening; one that
/// has not moved for two seconds turns away (<see cref="Stuck"/>). Positions are filtered
/// (<see cref="FishTrack"/>, <see cref="BallTrack"/>). Works in a frame where the team's box is at +x
/// (mirrored for the left end). It draws its plan (<see cref="DebugDraw"/>, shown with
/// <c>run --debug-draw</c>): per fish the planned route of its ball into the box, the ball circled,
/// the point the ball heads for and what the fish is doing (<c>push ball N</c>, <c>fetch ball N</c>,
/// <c>leave box</c>, <c>wait</c>).
/// </summary>
internal sealed class BallGrabDemo(IGoalBoxGame referee, string teamName = "ball-grab demo") : IStrategy
{
    private const int PushVCode = 6;
    private const int FineVCode = 4;

    // Cycles a fish spends on one ball before it leaves that ball alone for as long and takes another.
    private const int GiveUpCycles = 600;
    private const float Ahead = 300f;

    private const int RouteColour = 0x2e8b57; // the ball's planned route into the box
    private const int TargetColour = 0xffd400; // the target ball and the point it heads for

    private int[] _target = [];
    private Stuck[] _stuck = [];
    private Pusher[] _pushers = [];
    private int[] _since = [];
    private int[] _restUntil = [];
    private readonly Tracking _tracking = new();
    private int _restarts = -1;

    /// <inheritdoc/>
    public string TeamName => teamName;

    /// <inheritdoc/>
    public void Decide(MatchSnapshot snapshot, ReadOnlySpan<int> fish, Span<Decision> decisions)
    {
        if (_target.Length != fish.Length || referee.Restarts != _restarts)
        {
            // A new half: the referee has placed every body afresh.
            _restarts = referee.Restarts;
            _target = new int[fish.Length];
            _stuck = new Stuck[fish.Length];
            _pushers = new Pusher[fish.Length];
            _tracking.Restart();
            _since = new int[fish.Length];
            _restUntil = new int[snapshot.Balls.Length];
            Array.Fill(_target, -1);
        }

        var around = _tracking.Observe(snapshot, fish);
        int team = snapshot.Fish[fish[0]].Team;
        int side = referee.BoxSide(team);
        Span<Vector2> route = stackalloc Vector2[5];
        for (int k = 0; k < fish.Length; k++)
        {
            FishView me = snapshot.Fish[fish[k]];
            if (_stuck[k].Escaping(me, out Decision escape))
            {
                decisions[k] = escape;
                continue;
            }

            FishView mine = me with { Position = new Vector2(me.Position.X * side, me.Position.Y), Heading = side > 0 ? me.Heading : Angle.Wrap(MathF.PI - me.Heading) };
            if (BoxExit(mine, out Vector2 exit))
            {
                Decision e = Steering.SwimTo(mine, exit, 4);
                decisions[k] = side > 0 ? e : new Decision(e.VCode, 14 - e.TCode);
                if (DebugDraw.IsOn)
                {
                    Vector2 to = exit * new Vector2(side, 1f);
                    DebugDraw.Line(me.Position, to, me.Index);
                    DebugDraw.Point(to, me.Index, TargetColour);
                    DebugDraw.Text(to + new Vector2(20f, -20f), "leave box", me.Index);
                }

                continue;
            }

            int ball = Choose(snapshot, team, side, k);
            if (ball != _target[k])
            {
                _since[k] = snapshot.Cycle;
            }
            else if (ball >= 0 && snapshot.Cycle - _since[k] > GiveUpCycles)
            {
                // Too long on one ball: leave it alone for a while and take another.
                _restUntil[ball] = snapshot.Cycle + GiveUpCycles;
                ball = Choose(snapshot, team, side, k);
                _since[k] = snapshot.Cycle;
            }

            _target[k] = ball;
            if (ball < 0)
            {
                decisions[k] = Vector2.Distance(_tracking.Fish[k].Position, Vector2.Zero) < 200f ? Decision.Stop : _pushers[k].Travel(me, _tracking.Fish[k], Vector2.Zero, around, 6);
                if (DebugDraw.IsOn)
                {
                    DebugDraw.Line(me.Position, Vector2.Zero, me.Index);
                    DebugDraw.Text(new Vector2(20f, -20f), "wait", me.Index);
                }

                continue;
            }

            float radius = snapshot.Balls[ball].Radius;
            Vector2 q = _tracking.Balls[ball].Position * new Vector2(side, 1f);
            int n = Route(q, radius, route);
            Vector2 way = default(RouteProgress).Direction(route[..n], q, Ahead) * new Vector2(side, 1f);
            int vcode = q.X > BoxOuterX - 100f ? FineVCode : PushVCode;
            decisions[k] = _pushers[k].Push(me, _tracking.Fish[k], ref _tracking.Balls[ball], radius, way, around, vcode);
            if (DebugDraw.IsOn)
            {
                Draw(me, route[..n], side, radius, way, _pushers[k].Pushing, ball);
            }
        }
    }

    // The plan of one fish in world coordinates: its ball's route into the box (box frame, mirrored
    // back by side), the ball circled, the point 300 mm ahead it heads for, and what the fish is doing.
    private static void Draw(in FishView me, ReadOnlySpan<Vector2> route, int side, float radius, Vector2 way, bool pushing, int ball)
    {
        var mirror = new Vector2(side, 1f);
        Vector2 at = route[0] * mirror;
        Vector2 head = Steering.Head(me);
        if (!pushing)
        {
            DebugDraw.Line(head, at, me.Index);
        }

        for (int i = 1; i < route.Length; i++)
        {
            DebugDraw.Line(route[i - 1] * mirror, route[i] * mirror, me.Index, RouteColour);
        }

        DebugDraw.Circle(at, radius + 12f, me.Index, TargetColour);
        Vector2 aim = at + (way * Ahead);
        DebugDraw.Line(at, aim, me.Index, TargetColour);
        DebugDraw.Point(aim, me.Index, TargetColour);
        DebugDraw.Text(at + new Vector2(radius + 20f, -radius - 20f), (pushing ? "push ball " : "fetch ball ") + ball.ToString(CultureInfo.InvariantCulture), me.Index);
    }

    // The route of a ball at q (box frame) into the box: from the ball past the bar end on its side,
    // round it into the channel, down the channel to beside the opening, diagonally into the box.
    private static int Route(Vector2 q, float radius, Span<Vector2> route)
    {
        float s = q.Y >= 0f ? 1f : -1f;
        float barOuter = BarZ + (BarWidth / 2f);
        Vector2 pastBar = new(BackX - 150f, s * (barOuter + radius + 90f));
        Vector2 channel = new(1290f, s * (barOuter + radius + 110f));
        Vector2 beside = new(1240f, s * 380f);
        Vector2 inside = new(BackX + radius, s * 40f);
        int n = 0;
        route[n++] = q;
        bool inChannel = q.X > BoxOuterX + radius - 20f;
        if (!inChannel)
        {
            if (q.X < pastBar.X && MathF.Abs(q.Y) < MathF.Abs(pastBar.Y) + 200f)
            {
                route[n++] = pastBar;
            }

            route[n++] = channel;
            route[n++] = beside;
        }
        else if (MathF.Abs(q.Y) > MathF.Abs(beside.Y) + 60f)
        {
            route[n++] = beside;
        }

        route[n++] = inside;
        return n;
    }

    // A fish inside either box (a U open toward its end wall, too short for the fish to turn in
    // across it) whose head points at the back wall swims along the back wall first and then out
    // through the opening; without this it stays pressed against the back wall trying to reach the field.
    private static bool BoxExit(in FishView me, out Vector2 exit)
    {
        float ax = MathF.Abs(me.Position.X), sx = me.Position.X >= 0f ? 1f : -1f;
        exit = default;
        if (ax < BackX - 20f || ax > BoxOuterX + 40f || MathF.Abs(me.Position.Y) > BoxHalfWidth + 10f)
        {
            return false;
        }

        float outward = MathF.Cos(me.Heading) * sx; // > 0: facing the opening
        float sz = me.Position.Y >= 0f ? 1f : -1f;
        exit = outward > 0.5f
            ? new Vector2(sx * (HalfLength - 150f), me.Position.Y)
            : new Vector2(sx * (BoxInnerX + 80f), sz * (BoxHalfWidth - 40f)) + (new Vector2(sx * 150f, 0f) * MathF.Max(0f, outward + 0.5f));
        return true;
    }

    // The unscored ball with the best value per metre, not in a box already, not the partner's.
    private int Choose(MatchSnapshot snapshot, int team, int side, int k)
    {
        var balls = snapshot.Balls;
        int best = -1;
        float bestScore = float.NegativeInfinity;
        for (int i = 0; i < balls.Length; i++)
        {
            if (referee.HasScored(team, i) || snapshot.Cycle < _restUntil[i] || InBox(_tracking.Balls[i].Position, balls[i].Radius, side) || InBox(_tracking.Balls[i].Position, balls[i].Radius, -side) || Taken(i, k))
            {
                continue;
            }

            float value = (float)referee.BallValue(i);
            float distance = Vector2.Distance(_tracking.Fish[k].Position, _tracking.Balls[i].Position) + 200f;
            float score = (value / distance) + (i == _target[k] ? 0.0015f : 0f);
            if (MathF.Abs(_tracking.Balls[i].Position.X) > HalfLength - 120f)
            {
                // Against an end wall no fish gets behind it to push it out: last of all.
                score *= 0.01f;
            }

            if (score > bestScore)
            {
                bestScore = score;
                best = i;
            }
        }

        return best;
    }

    private bool Taken(int ball, int k)
    {
        for (int j = 0; j < _target.Length; j++)
        {
            if (j != k && _target[j] == ball)
            {
                return true;
            }
        }

        return false;
    }
}
