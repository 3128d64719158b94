using URWPGSim2D.Collision.Motion;
using URWPGSim2D.Engine.Items.Demo;

namespace URWPGSim2D.Engine.Items.Transport;

/// <summary>
/// The demo strategy of 水中搬运. The six balls stand in a triangle where most balls have another
/// right behind them, so they go in an order that keeps the pushed ball free in front and behind:
/// the back corners 3 and 5 first, each round the outside of the triangle (via (700, ∓420)), then
/// the apex 0, pushed out sideways (via (555, 235)) before it goes to its hole, then 1 and 2
/// straight, then 4 straight. Fish 0 takes 5, 2 and 4, fish 1 takes 3, 0 and 1; a fish whose next
/// ball is not free yet waits near its start. A fish not behind its ball goes to a stand point
/// behind it on the push line (at most x = 1200, so its tail stays off the wall), through a lane at
/// |z| = 650 when balls are in the way and slowly near balls, and turns on the spot toward the ball;
/// behind it, it pushes with <see cref="Pusher"/>, the lag-aware push that keeps the ball on the
/// head (gear 4, gear 2 in the last 150 mm), toward the route's waypoint, then through the hole's
/// centre. The balls' noisy observed positions are smoothed for the plan and filtered
/// (<see cref="BallTrack"/>, <see cref="FishTrack"/>) for the push. A ball not in after 150 s is
/// given up and the balls waiting for it are freed.
/// </summary>
internal sealed class TransportDemo(TransportReferee referee) : IStrategy
{
    private const int GiveUpCycles = 1500;
    private const float Beyond = 120f;
    private const float Fine = 150f;
    private const float Lane = 650f;
    private const int PushVCode = 4;
    private const int FineVCode = 2;
    private const float Smoothing = 0.5f;
    private const float Approach = 230f;
    private const float SlotX = 1200f;
    private static readonly int[][] Plans = [[5, 2, 4], [3, 0, 1]];

    // The waypoint of each ball's route before its hole (NaN: straight to the hole).
    private static readonly Vector2[] Waypoints =
    [
        new(555f, 235f), new(float.NaN), new(float.NaN), new(700f, -420f), new(float.NaN), new(700f, 420f),
    ];

    private readonly bool[] _abandoned = new bool[TransportLayout.Count];
    private Job[] _jobs = [];
    private Stuck[] _stuck = [];
    private bool[] _pushing = [];
    private Vector2[] _seen = [];
    private Pusher[] _pushers = [];
    private readonly Tracking _tracking = new();

    /// <inheritdoc/>
    public string TeamName => "transport demo";

    /// <inheritdoc/>
    public void Decide(MatchSnapshot snapshot, ReadOnlySpan<int> fish, Span<Decision> decisions)
    {
        if (_jobs.Length != fish.Length)
        {
            _jobs = new Job[fish.Length];
            Array.Fill(_jobs, new Job(-1, 0, 0));
            _stuck = new Stuck[fish.Length];
            _pushing = new bool[fish.Length];
            _pushers = new Pusher[fish.Length];
        }

        var around = _tracking.Observe(snapshot, fish);

        // The balls' observed positions are noisy (±30 mm): follow them smoothly, jumping only when a ball was knocked far.
        if (_seen.Length != snapshot.Balls.Length)
        {
            _seen = new Vector2[snapshot.Balls.Length];
            for (int i = 0; i < _seen.Length; i++)
            {
                _seen[i] = snapshot.Balls[i].Position;
            }
        }

        for (int i = 0; i < _seen.Length; i++)
        {
            Vector2 seen = snapshot.Balls[i].Position;
            _seen[i] = Vector2.Distance(seen, _seen[i]) > 150f ? seen : Vector2.Lerp(_seen[i], seen, Smoothing);
        }

        for (int k = 0; k < fish.Length; k++)
        {
            FishView me = snapshot.Fish[fish[k]];
            ref Job job = ref _jobs[k];
            if (job.Ball >= 0 && (Done(job.Ball) || snapshot.Cycle - job.Start > GiveUpCycles))
            {
                _abandoned[job.Ball] |= !referee.InHole(job.Ball);
                job = new Job(-1, 0, 0);
                _pushing[k] = false;
                _pushers[k] = default;
            }

            if (job.Ball < 0)
            {
                int ball = Next(k, snapshot.Balls.Length);
                if (ball >= 0)
                {
                    job = new Job(ball, float.IsNaN(Waypoints[ball].X) ? 1 : 0, snapshot.Cycle);
                }
            }

            if (_stuck[k].Escaping(me, out Decision escape))
            {
                decisions[k] = escape;
                continue;
            }

            decisions[k] = job.Ball < 0 ? Wait(me, k) : Push(snapshot, me, k, ref job, snapshot.Fish[fish[fish.Length - 1 - k]].Position, around);
        }
    }

    // The point 120 mm beyond the ball's hole on the line from the ball through it.
    private static Vector2 BeyondHole(int ball, Vector2 from)
    {
        Vector2 hole = TransportLayout.Holes[ball];
        Vector2 d = hole - from;
        return hole + (d.LengthSquared() > 1f ? Vector2.Normalize(d) * Beyond : Vector2.Zero);
    }

    private bool Done(int ball) => referee.InHole(ball) || _abandoned[ball];

    // The apex 0 waits for the back corners, 1 and 2 for 0 (it stands in their way), 4 for 1 and 2 (they box it in).
    private bool Ready(int ball) => ball switch
    {
        0 => Done(3) && Done(5),
        1 or 2 => Done(0),
        4 => Done(1) && Done(2),
        _ => true,
    };

    // The fish's next ball: its own plan first, then any ball left, never one the other fish is on.
    private int Next(int k, int balls)
    {
        int other = _jobs.Length > 1 ? _jobs[1 - Math.Min(k, 1)].Ball : -1;
        foreach (int ball in Plans[k % 2])
        {
            if (ball < balls && !Done(ball) && ball != other && Ready(ball))
            {
                return ball;
            }
        }

        for (int ball = 0; ball < Math.Min(balls, TransportLayout.Count); ball++)
        {
            if (!Done(ball) && ball != other && Ready(ball) && Array.IndexOf(Plans[(k + 1) % 2], ball) < 0)
            {
                return ball;
            }
        }

        return -1;
    }

    private Decision Push(MatchSnapshot snapshot, in FishView me, int k, ref Job job, Vector2 other, in Surroundings around)
    {
        BallView ball = snapshot.Balls[job.Ball];
        Vector2 b = _seen[job.Ball];
        Vector2 hole = TransportLayout.Holes[job.Ball], waypoint = Waypoints[job.Ball];
        if (job.Stage == 0 && (Vector2.Distance(b, waypoint) < 90f || Vector2.Distance(b, hole) < Vector2.Distance(waypoint, hole)))
        {
            job = job with { Stage = 1 };
        }

        Vector2 target = job.Stage == 0 ? waypoint : BeyondHole(job.Ball, b);
        Vector2 dir = Vector2.Normalize(target - b);
        Vector2 head = Steering.Head(me) - b;
        float headAlong = Vector2.Dot(head, dir), headAside = MathF.Abs((head.X * dir.Y) - (head.Y * dir.X));
        float error = MathF.Abs(Angle.Wrap(MathF.Atan2(dir.Y, dir.X) - me.Heading));
        _pushing[k] = _pushing[k]
            ? headAlong < ball.Radius * 0.5f && headAlong > -(ball.Radius + 700f) && headAside < MathF.Max(2f * ball.Radius, -headAlong * 0.8f) && error < 1.6f
            : headAlong < -ball.Radius * 0.2f && headAlong > -(ball.Radius + 600f) && headAside < MathF.Max(ball.Radius, -headAlong * 0.6f) && error < 1.3f;
        if (_pushing[k])
        {
            // Behind the ball (the same tolerances as Dribble's): the lag-aware push, which keeps the
            // ball on the head and curves it onto the line through the hole.
            Vector2 tracked = _tracking.Balls[job.Ball].Position;
            Vector2 toward = target - tracked;
            Vector2 way = toward.LengthSquared() > 1f ? Vector2.Normalize(toward) : dir;
            return _pushers[k].Push(me, _tracking.Fish[k], ref _tracking.Balls[job.Ball], ball.Radius, way, around, Vector2.Distance(b, hole) < Fine ? FineVCode : PushVCode);
        }

        // Not behind the ball: to the stand point behind it (x ≤ 1200 keeps the tail off the wall),
        // through the lane at |z| = 650 when balls are in the way, then turn on the spot toward the ball.
        float reach = (me.BodyLength * 0.5f) + me.HeadLength + ball.Radius;
        Vector2 stand = b - (dir * (reach + Approach));
        stand = new Vector2(MathF.Min(stand.X, SlotX), Math.Clamp(stand.Y, -800f, 800f));
        float distance = Vector2.Distance(me.Position, stand);
        if (distance < 60f)
        {
            return Dribble.Swim(me, b, 3);
        }

        float side = MathF.Abs(stand.Y) > 50f ? MathF.Sign(stand.Y) : (k == 0 ? 1f : -1f);
        Vector2 lane = new(stand.X, side * Lane);
        bool inSlot = stand.X > SlotX - 120f && MathF.Abs(stand.Y) < 450f;
        if (inSlot && other.X > SlotX - 120f && MathF.Abs(other.Y) < 450f)
        {
            // The other fish is between the triangle and the wall: wait in the lane.
            return Vector2.Distance(me.Position, lane) < 100f ? Decision.Stop : Steering.SwimTo(me, lane, 8);
        }

        // Slowly near the balls, where a turning fish sweeps them with its tail.
        int fast = Near(snapshot.Balls, me.Position, 450f) ? 4 : 10;
        if (Clear(snapshot.Balls, me.Position, stand) || Vector2.Distance(me.Position, lane) < 100f)
        {
            return Steering.SwimTo(me, stand, distance < 300f ? 4 : fast);
        }

        // Balls in the way: along the lane to above (or below) the stand point, into the lane first.
        bool inLane = MathF.Abs(me.Position.Y - lane.Y) < 80f;
        return Steering.SwimTo(me, inLane || Clear(snapshot.Balls, me.Position, lane) ? lane : new Vector2(me.Position.X, lane.Y), Vector2.Distance(me.Position, lane) < 400f ? 4 : fast);
    }

    // Whether a ball is within d of p.
    private static bool Near(ReadOnlySpan<BallView> balls, Vector2 p, float d)
    {
        foreach (ref readonly var ball in balls)
        {
            if (Vector2.DistanceSquared(ball.Position, p) < d * d)
            {
                return true;
            }
        }

        return false;
    }

    // Whether the way from a to b keeps a fish clear of every ball.
    private static bool Clear(ReadOnlySpan<BallView> balls, Vector2 a, Vector2 b)
    {
        Vector2 d = b - a;
        float length2 = MathF.Max(d.LengthSquared(), 1f);
        foreach (ref readonly var ball in balls)
        {
            float t = Math.Clamp(Vector2.Dot(ball.Position - a, d) / length2, 0f, 1f);
            if (Vector2.Distance(a + (d * t), ball.Position) < ball.Radius + 150f)
            {
                return false;
            }
        }

        return true;
    }

    private static Decision Wait(in FishView me, int k)
    {
        Vector2 spot = new(-1000f, k == 0 ? 600f : -600f);
        return Vector2.Distance(me.Position, spot) < 150f ? Decision.Stop : Steering.SwimTo(me, spot, 8);
    }

    // A fish's ball (−1: none), the stage of its route (0: to the waypoint, 1: over the hole) and the cycle it started.
    private readonly record struct Job(int Ball, int Stage, int Start);
}
