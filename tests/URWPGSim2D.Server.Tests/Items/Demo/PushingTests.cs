using URWPGSim2D.Collision.Motion;
using URWPGSim2D.Engine.Items.Demo;
using URWPGSim2D.Engine.Matches;

namespace URWPGSim2D.Server.Tests.Items.Demo;

/// <summary>
/// The lag-aware push (<see cref="Pusher"/>) and what it stands on (<see cref="FishTrack"/>,
/// <see cref="BallTrack"/>, <see cref="RouteProgress"/>), played in open water with the reference's
/// noise on and checked against the world's true state.
/// </summary>
public sealed class PushingTests
{
    // A fish that stays still far from everything (the strategy is called for its team's fish).
    private static readonly FishDefinition Bystander = new(0, new Vector2(-1900f, 1200f), 0f, "idle", Decision.Stop);

    [Fact]
    public void TracksAreCloserToTheTruthThanTheViews()
    {
        // A fish swims a wide curve while a ball rolls; the views are ±30 mm / ±5° off.
        var watcher = new Watcher { Swim = true };
        var match = Open([new FishDefinition(0, new Vector2(-1500f, -1000f), 0f, "idle", Decision.Stop)], [new BallDefinition(new Vector2(0f, 500f), new Vector2(300f, 0f), 58f)], watcher, seed: 3);
        watcher.Match = match;
        match.Play(300);

        Assert.True(watcher.FishTrackError.Rms() < 0.5 * watcher.FishViewError.Rms(), $"fish: track {watcher.FishTrackError.Rms():F1} mm, view {watcher.FishViewError.Rms():F1} mm");
        Assert.True(watcher.HeadingTrackError.Rms() < 0.5 * watcher.HeadingViewError.Rms(), $"heading: track {watcher.HeadingTrackError.Rms():F4}, view {watcher.HeadingViewError.Rms():F4}");
        Assert.True(watcher.BallTrackError.Rms() < 0.5 * watcher.BallViewError.Rms(), $"ball: track {watcher.BallTrackError.Rms():F1} mm, view {watcher.BallViewError.Rms():F1} mm");
    }

    [Fact]
    public void AFreelyRollingBallShowsNoImpulseAndAHitOneDoes()
    {
        // A ball slowing down through every drag band (300 mm/s to rest) is hit by nothing: the
        // impulse, the change of velocity with the cycle's drag undone, is zero every cycle.
        var watcher = new Watcher();
        var match = Open([Bystander], [new BallDefinition(new Vector2(-1500f, 0f), new Vector2(300f, 0f), 58f)], watcher, seed: 5);
        watcher.Match = match;
        match.Play(120);
        Assert.All(watcher.Impulses, i => Assert.True(i < 1e-3f, $"impulse {i} mm/s"));

        // Against a wall it stops dead: that is an impulse.
        var wall = new Watcher();
        var hit = Open([Bystander], [new BallDefinition(new Vector2(2000f, 0f), new Vector2(300f, 0f), 58f)], wall, seed: 5);
        wall.Match = hit;
        hit.Play(30);
        Assert.Contains(wall.Impulses, i => i > 100f);
    }

    [Theory]
    [InlineData(1UL)]
    [InlineData(2UL)]
    [InlineData(3UL)]
    [InlineData(4UL)]
    public void AFishPushesABallTwoMetresFromAnyStartWithoutLosingIt(ulong seed)
    {
        // The fish starts 250–650 mm from the ball, facing anywhere; the ball must go 2 m toward +x.
        var rng = new Random((int)seed);
        float angle = (float)(rng.NextDouble() * 2 * Math.PI), distance = 250f + ((float)rng.NextDouble() * 400f);
        Vector2 ball = new(-1200f, (float)(rng.NextDouble() * 600) - 300f);
        Vector2 fish = ball + (new Vector2(MathF.Cos(angle), MathF.Sin(angle)) * distance);
        float heading = (float)((rng.NextDouble() * 2 * Math.PI) - Math.PI);
        var pusher = new RouteStrategy([ball, new Vector2(1500f, ball.Y)]);
        var match = Open([new FishDefinition(0, fish, heading, "idle", Decision.Stop)], [new BallDefinition(ball, Vector2.Zero, 58f)], pusher, seed);
        int cycles = 0;
        while (match.World.Balls[0].Position.X < ball.X + 2000f && cycles < 900)
        {
            match.Step();
            cycles++;
        }

        // Pushing starts once and stops no more: the ball is never lost.
        Assert.True(cycles < 900, $"seed {seed}: the ball got to x = {match.World.Balls[0].Position.X:F0} in 90 s");
        Assert.True(pusher.Starts <= 2, $"seed {seed}: the fish started pushing {pusher.Starts} times");
        Assert.InRange(match.World.Balls[0].Position.Y, ball.Y - 250f, ball.Y + 250f);
    }

    [Fact]
    public void APushedBallRoundsARightAngleCloseToItsRoute()
    {
        // Straight on for 800 mm, then a quarter turn: the ball stays within 250 mm of the route, on the fish's head.
        Vector2[] route = [new(-1300f, 0f), new(-500f, 0f), new(-500f, 1000f), new(-500f, 2000f)];
        foreach (ulong seed in new ulong[] { 1, 2, 3 })
        {
            var pusher = new RouteStrategy(route);
            var match = Open([new FishDefinition(0, new Vector2(-1530f, 0f), 0f, "idle", Decision.Stop)], [new BallDefinition(route[0], Vector2.Zero, 58f)], pusher, seed);
            float worst = 0f;
            int cycles = 0;
            while (match.World.Balls[0].Position.Y < 900f && cycles < 900)
            {
                match.Step();
                worst = MathF.Max(worst, Distance(route, match.World.Balls[0].Position));
                cycles++;
            }

            Assert.True(cycles < 900, $"seed {seed}: the ball is at {match.World.Balls[0].Position} after 90 s");
            Assert.True(worst < 250f, $"seed {seed}: the ball went {worst:F0} mm off its route");
            Assert.Equal(1, pusher.Starts);
        }
    }

    [Fact]
    public void RouteProgressHeadsOnAlongTheRouteAndBackOntoIt()
    {
        Vector2[] route = [new(0f, 0f), new(1000f, 0f), new(1000f, 1000f)];
        var progress = new RouteProgress();

        // On the first leg: straight along it.
        var d = progress.Direction(route, new Vector2(200f, 0f), 300f);
        Assert.Equal(1f, d.X, 3);

        // 100 mm off it: toward a point 400 mm ahead on it (300 + the offset).
        d = progress.Direction(route, new Vector2(300f, 100f), 300f);
        Assert.Equal(MathF.Atan2(-100f, 400f), MathF.Atan2(d.Y, d.X), 3);

        // Past the corner's bisector: on the second leg, and it does not go back.
        d = progress.Direction(route, new Vector2(1000f, 300f), 300f);
        Assert.Equal(1, progress.Leg);
        Assert.Equal(1f, d.Y, 3);
        progress.Direction(route, new Vector2(600f, 0f), 300f);
        Assert.Equal(1, progress.Leg);

        // Lost far from the route: it restarts from the nearest leg.
        progress.Direction(route, new Vector2(200f, -600f), 300f);
        Assert.Equal(0, progress.Leg);
    }

    private static Match Open(List<FishDefinition> fish, List<BallDefinition> balls, IStrategy strategy, ulong seed)
    {
        var scenario = new ScenarioDefinition
        {
            FieldLength = 4500f, FieldWidth = 3000f, GoalBlocks = false, Cycles = 3000, Seed = seed, Fish = fish, Balls = balls,
        };
        return MatchBuilder.Build(scenario, [new TeamStrategy("test", strategy, false), null], seed: seed, noise: true);
    }

    private static float Distance(Vector2[] route, Vector2 p)
    {
        float best = float.PositiveInfinity;
        for (int i = 0; i + 1 < route.Length; i++)
        {
            Vector2 a = route[i], ab = route[i + 1] - a;
            float t = Math.Clamp(Vector2.Dot(p - a, ab) / ab.LengthSquared(), 0f, 1f);
            best = MathF.Min(best, Vector2.Distance(p, a + (ab * t)));
        }

        return best;
    }

    // Pushes ball 0 along a route with fish 0, counting how often it starts pushing.
    private sealed class RouteStrategy(Vector2[] route) : IStrategy
    {
        private FishTrack _me;
        private BallTrack _ball;
        private Pusher _pusher;
        private RouteProgress _progress;
        private ObstacleField? _field;
        private Waypath? _ways;
        private bool _was;

        public int Starts { get; private set; }

        public string TeamName => "push";

        public void Decide(MatchSnapshot snapshot, ReadOnlySpan<int> fish, Span<Decision> decisions)
        {
            var view = snapshot.Fish[fish[0]];
            _me.Update(view);
            _ball.Update(snapshot.Balls[0]);
            _field ??= new ObstacleField(snapshot);
            _ways ??= new Waypath(_field);
            Vector2 direction = _progress.Direction(route, _ball.Position, 350f);
            decisions[0] = _pusher.Push(view, _me, ref _ball, snapshot.Balls[0].Radius, direction, new Surroundings(_field, _ways), 6);
            if (_pusher.Pushing && !_was)
            {
                Starts++;
            }

            _was = _pusher.Pushing;
        }
    }

    // Swims fish 0 in a slow S (when asked) and compares the tracks with the truth.
    private sealed class Watcher : IStrategy
    {
        private FishTrack _fish;
        private BallTrack _ball;

        public Match? Match { get; set; }

        public bool Swim { get; init; }

        public List<float> FishTrackError { get; } = [];

        public List<float> FishViewError { get; } = [];

        public List<float> HeadingTrackError { get; } = [];

        public List<float> HeadingViewError { get; } = [];

        public List<float> BallTrackError { get; } = [];

        public List<float> BallViewError { get; } = [];

        public List<float> Impulses { get; } = [];

        public string TeamName => "watch";

        public void Decide(MatchSnapshot snapshot, ReadOnlySpan<int> fish, Span<Decision> decisions)
        {
            var world = Match!.World;
            if (Swim)
            {
                var view = snapshot.Fish[fish[0]];
                _fish.Update(view);
                if (snapshot.Cycle > 20)
                {
                    var truth = world.Fish[fish[0]];
                    FishTrackError.Add(Vector2.Distance(_fish.Position, truth.Position));
                    FishViewError.Add(Vector2.Distance(view.Position, truth.Position));
                    HeadingTrackError.Add(Angle.Wrap(_fish.Heading - truth.Heading));
                    HeadingViewError.Add(Angle.Wrap(view.Heading - truth.Heading));
                }

                decisions[0] = new Decision(4, snapshot.Cycle < 150 ? 8 : 6);
            }

            _ball.Update(snapshot.Balls[0]);
            if (snapshot.Cycle > 20 && world.Balls[0].Velocity != Vector2.Zero)
            {
                BallTrackError.Add(Vector2.Distance(_ball.Position, world.Balls[0].Position));
                BallViewError.Add(Vector2.Distance(snapshot.Balls[0].Position, world.Balls[0].Position));
            }

            if (snapshot.Cycle > 0)
            {
                Impulses.Add(_ball.Impulse.Length());
            }
        }
    }
}

/// <summary>Root mean square of a list of errors.</summary>
internal static class ErrorStatistics
{
    /// <summary>√(mean of squares).</summary>
    public static double Rms(this List<float> errors) => Math.Sqrt(errors.Average(e => (double)e * e));
}
