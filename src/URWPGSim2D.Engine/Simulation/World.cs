using URWPGSim2D.Collision.Fish;
using URWPGSim2D.Collision.Motion;
using URWPGSim2D.Collision.Pool;
using URWPGSim2D.Collision.Shapes;

namespace URWPGSim2D.Engine.Simulation;

/// <summary>
/// The pool and everything in it: the field (walls, goal blocks), fish, balls and obstacles, plus
/// the match clock (the score is the match's rules'). The bodies themselves live in the motion world (<see cref="Motion"/>,
/// the collision library's <see cref="MotionWorld"/>), each tagged with what it is and its index here
/// (<see cref="BodyTag"/>); the fish and balls here hold the game state and their body's handle.
/// Arrays are fixed for the whole match; iteration is always by index.
/// </summary>
public sealed class World
{
    private readonly BodyId[] _staticHandles;

    /// <summary>Creates the world over a motion world that already holds its fish and balls (each tagged by its state); adds the static bodies and the walls, tagged likewise.</summary>
    public World(MotionWorld motion, Field field, FishState[] fish, BallState[] balls, ObstacleView[] obstacles, StaticBody[] statics)
    {
        Motion = motion;
        Field = field;
        Fish = fish;
        Balls = balls;
        Obstacles = obstacles;
        Statics = statics;
        _staticHandles = new BodyId[statics.Length];
        for (int i = 0; i < statics.Length; i++)
        {
            StaticBody s = statics[i];
            Shape shape = s.Kind switch
            {
                ShapeKind.Circle => s.Circle,
                ShapeKind.Polygon => s.Polygon,
                _ => s.Box,
            };
            _staticHandles[i] = motion.AddStatic(shape);
            motion.SetTag(_staticHandles[i], BodyTag.Static(i));
        }

        WallsHandle = motion.AddWalls(field);
        motion.SetTag(WallsHandle, BodyTag.Walls);
    }

    /// <summary>The motion world: every body's pose, joints, shape and in-cycle motion.</summary>
    public MotionWorld Motion { get; }

    /// <summary>
    /// Whether a fish's tail turns to the cycle's wave pose over the cycle, swept like any motion
    /// (<see cref="MotionWorld.SetJointTargets"/>), instead of taking it at the cycle's start (false:
    /// the pinned traces' model, until the contact model that comes with it is complete).
    /// </summary>
    internal bool TailSweeps { get; set; }

    /// <summary>The walls' handle in the motion world.</summary>
    public BodyId WallsHandle { get; }

    /// <summary>The pool: bounds, walls, goal blocks, goal mouths.</summary>
    public Field Field { get; }

    /// <summary>Every fish by index (fishN).</summary>
    public FishState[] Fish { get; }

    /// <summary>Every ball by index (ballN).</summary>
    public BallState[] Balls { get; }

    /// <summary>Obstacle descriptions by index (obstacleN).</summary>
    public ObstacleView[] Obstacles { get; }

    /// <summary>Obstacles (first, obstacleN = index) then goal blocks (goalBlockN = index − obstacle count).</summary>
    public StaticBody[] Statics { get; }

    /// <summary>Cycles completed.</summary>
    public int Cycle { get; set; }

    /// <summary>The teams that play: 2, or more when a fish plays for a team numbered 2 or higher (four-teams).</summary>
    public int TeamCount
    {
        get
        {
            int teams = 2;
            foreach (var f in Fish)
            {
                teams = Math.Max(teams, f.Team + 1);
            }

            return teams;
        }
    }

    /// <summary>The team that scores when a ball ends in the goal on <paramref name="side"/> (−1 left, +1 right): team 0 attacks the right goal (+X), team 1 the left one.</summary>
    public static int ScoringTeam(int side) => side > 0 ? 0 : 1;

    /// <summary>Match time in seconds, cycles × 0.1 (exact decimal multiple, no drift).</summary>
    public double Time => Cycle * 0.1;

    /// <summary>Number of fish of a team.</summary>
    public int CountTeam(int team)
    {
        int n = 0;
        foreach (var f in Fish)
        {
            n += f.Team == team ? 1 : 0;
        }

        return n;
    }

    /// <summary>The contact of a pair at the bodies' poses now (MTV moves A).</summary>
    public Contact Detect(in CandidatePair pair) => Motion.Detect(HandleOfA(pair), HandleOfB(pair));

    /// <summary>Every leaf contact of a pair whose A is a fish (with a fish, a ball or a static body) at the bodies' poses now; the MTVs move the fish.</summary>
    public int DetectLeaves(in CandidatePair pair, Span<FishContact> contacts) => Motion.DetectLeaves(HandleOfA(pair), HandleOfB(pair), contacts);

    /// <summary>The world's pair of a contact the motion world reports, found from the bodies' tags.</summary>
    public CandidatePair PairOf(in Contact contact)
    {
        int tagA = Motion.TagOf(contact.BodyA), tagB = Motion.TagOf(contact.BodyB);
        int a = BodyTag.IndexOf(tagA), b = BodyTag.IndexOf(tagB);
        PairKind kind = (BodyTag.RoleOf(tagA), BodyTag.RoleOf(tagB)) switch
        {
            (BodyRole.Fish, BodyRole.Fish) => PairKind.FishFish,
            (BodyRole.Fish, BodyRole.Ball) => PairKind.FishBall,
            (BodyRole.Fish, BodyRole.Static) => PairKind.FishStatic,
            (BodyRole.Fish, BodyRole.Walls) => PairKind.FishWall,
            (BodyRole.Ball, BodyRole.Ball) => PairKind.BallBall,
            (BodyRole.Ball, BodyRole.Static) => PairKind.BallStatic,
            (BodyRole.Ball, BodyRole.Walls) => PairKind.BallWall,
            _ => throw new InvalidOperationException($"the motion world reported a contact of {contact.BodyA} and {contact.BodyB} tagged {tagA} and {tagB}, not a pair of the match"),
        };
        return new CandidatePair(kind, a, b, 0f);
    }

    private BodyId HandleOfA(in CandidatePair p) => p.Kind is PairKind.FishFish or PairKind.FishBall or PairKind.FishStatic or PairKind.FishWall ? Fish[p.A].Handle : Balls[p.A].Handle;

    private BodyId HandleOfB(in CandidatePair p) => p.Kind switch
    {
        PairKind.FishFish => Fish[p.B].Handle,
        PairKind.FishBall or PairKind.BallBall => Balls[p.B].Handle,
        PairKind.FishStatic or PairKind.BallStatic => _staticHandles[p.B],
        _ => WallsHandle,
    };
}
