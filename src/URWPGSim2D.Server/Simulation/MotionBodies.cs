using System.Numerics;
using URWPGSim2D.Collision.BroadPhase;
using URWPGSim2D.Collision.Fish;
using URWPGSim2D.Collision.Motion;
using URWPGSim2D.Collision.Shapes;

namespace URWPGSim2D.Server.Simulation;

/// <summary>
/// The world's bodies in the collision library's motion <see cref="Stepper"/>: fish, then balls
/// (its moving bodies), then obstacles and goal blocks (static), then the walls, with the mapping
/// between the stepper's body ids and the world's fish, balls and static bodies. Within a cycle
/// the stepper owns where the bodies are; the world's poses are brought up to date around each
/// contact response (<see cref="Pull"/>, <see cref="Push"/>) and at the end of the cycle.
/// </summary>
internal sealed class MotionBodies
{
    private readonly World _world;
    private readonly int _fish;
    private readonly int _balls;
    private readonly int _statics;
    private readonly float[] _joints;

    public MotionBodies(World world, BroadPhaseKind broadPhase)
    {
        _world = world;
        _fish = world.Fish.Length;
        _balls = world.Balls.Length;
        _statics = world.Statics.Length;
        _joints = new float[3 * _fish];
        Stepper = new Stepper(broadPhase);
        foreach (var f in world.Fish)
        {
            Stepper.AddFish(f.Size, new FishPose(f.Position, f.Heading, f.Joint1, f.Joint2, f.Joint3));
            _joints[3 * f.Index] = f.Joint1;
            _joints[(3 * f.Index) + 1] = f.Joint2;
            _joints[(3 * f.Index) + 2] = f.Joint3;
        }

        foreach (var b in world.Balls)
        {
            Stepper.AddCircle(b.Radius, b.Position);
        }

        foreach (var s in world.Statics)
        {
            Shape shape = s.Kind switch
            {
                ShapeKind.Circle => s.Circle,
                ShapeKind.Polygon => s.Polygon,
                _ => s.Box,
            };
            Stepper.AddStatic(shape);
        }

        WallsId = Stepper.AddWalls(world.Field);
    }

    /// <summary>The library's stepper over the world's bodies.</summary>
    public Stepper Stepper { get; }

    /// <summary>The walls' body id.</summary>
    public int WallsId { get; }

    /// <summary>Brings every moving body of the stepper up to the world: poses changed outside the stepper (jumps), joints, velocities with noise.</summary>
    public void PushAll()
    {
        for (int id = 0; id < _fish + _balls; id++)
        {
            Push(id);
        }
    }

    /// <summary>Brings every body of the world up to the stepper's poses.</summary>
    public void PullAll()
    {
        for (int id = 0; id < _fish + _balls; id++)
        {
            Pull(id);
        }
    }

    /// <summary>Gives the stepper the world's pose (when it differs), joints and motion of a moving body.</summary>
    public void Push(int id)
    {
        PushPose(id);
        if (id < _fish)
        {
            var f = _world.Fish[id];
            int j = 3 * id;
            if (_joints[j] != f.Joint1 || _joints[j + 1] != f.Joint2 || _joints[j + 2] != f.Joint3)
            {
                Stepper.SetJoints(id, f.Joint1, f.Joint2, f.Joint3);
                (_joints[j], _joints[j + 1], _joints[j + 2]) = (f.Joint1, f.Joint2, f.Joint3);
            }

            Stepper.SetVelocity(id, f.Velocity + f.NoiseVelocity, f.AngularVelocity + f.NoiseAngularVelocity);
            if (Stepper.CollidesOf(id) == f.OutOfPlay)
            {
                Stepper.SetCollides(id, !f.OutOfPlay); // a fish a competition item parked meets nothing
            }
        }
        else if (id < _fish + _balls)
        {
            var b = _world.Balls[id - _fish];
            Stepper.SetVelocity(id, b.Velocity + b.NoiseVelocity);
            if (Stepper.CollidesOf(id) == b.OutOfPlay)
            {
                Stepper.SetCollides(id, !b.OutOfPlay); // a ball a competition item took out of play (potted) meets nothing
            }
        }
    }

    /// <summary>Gives the world the stepper's pose of a moving body (static bodies and walls: nothing).</summary>
    public void Pull(int id)
    {
        if (id < _fish)
        {
            var f = _world.Fish[id];
            Vector2 position = Stepper.PositionOf(id);
            float heading = Stepper.HeadingOf(id);
            if (position != f.Position || heading != f.Heading)
            {
                f.Position = position;
                f.Heading = heading;
                f.Invalidate();
            }
        }
        else if (id < _fish + _balls)
        {
            _world.Balls[id - _fish].Position = Stepper.PositionOf(id);
        }
    }

    /// <summary>Gives the world a fish's joints as the stepper holds them (after a rejected move).</summary>
    public void PullJoints(int fish)
    {
        FishPose pose = Stepper.FishModelOf(fish).Pose;
        var f = _world.Fish[fish];
        (f.Joint1, f.Joint2, f.Joint3) = (pose.Joint1, pose.Joint2, pose.Joint3);
        (_joints[3 * fish], _joints[(3 * fish) + 1], _joints[(3 * fish) + 2]) = (pose.Joint1, pose.Joint2, pose.Joint3);
        f.Invalidate();
    }

    /// <summary>Whether a body id is a fish.</summary>
    public bool IsFish(int id) => id < _fish;

    /// <summary>The contact of a pair at the world's poses now (MTV moves A).</summary>
    public Contact Detect(in CandidatePair pair)
    {
        int a = IdOfA(pair), b = IdOfB(pair);
        PushPose(a);
        PushPose(b);
        return Stepper.Detect(a, b);
    }

    /// <summary>The world's pair for a contact of the stepper.</summary>
    public CandidatePair PairOf(in Contact contact)
    {
        int a = contact.BodyA, b = contact.BodyB;
        if (a < _fish)
        {
            return b < _fish ? new CandidatePair(PairKind.FishFish, a, b, 0f)
                : b < _fish + _balls ? new CandidatePair(PairKind.FishBall, a, b - _fish, 0f)
                : b == WallsId ? new CandidatePair(PairKind.FishWall, a, 0, 0f)
                : new CandidatePair(PairKind.FishStatic, a, b - _fish - _balls, 0f);
        }

        int ball = a - _fish;
        return b < _fish + _balls ? new CandidatePair(PairKind.BallBall, ball, b - _fish, 0f)
            : b == WallsId ? new CandidatePair(PairKind.BallWall, ball, 0, 0f)
            : new CandidatePair(PairKind.BallStatic, ball, b - _fish - _balls, 0f);
    }

    private int IdOfA(in CandidatePair p) => p.Kind is PairKind.FishFish or PairKind.FishBall or PairKind.FishStatic or PairKind.FishWall ? p.A : _fish + p.A;

    private int IdOfB(in CandidatePair p) => p.Kind switch
    {
        PairKind.FishFish => p.B,
        PairKind.FishBall or PairKind.BallBall => _fish + p.B,
        PairKind.FishStatic or PairKind.BallStatic => _fish + _balls + p.B,
        _ => WallsId,
    };

    private void PushPose(int id)
    {
        if (id < _fish)
        {
            var f = _world.Fish[id];
            if (Stepper.PositionOf(id) != f.Position || Stepper.HeadingOf(id) != f.Heading)
            {
                Stepper.SetPose(id, f.Position, f.Heading);
            }
        }
        else if (id < _fish + _balls)
        {
            var b = _world.Balls[id - _fish];
            if (Stepper.PositionOf(id) != b.Position)
            {
                Stepper.SetPose(id, b.Position, 0f);
            }
        }
    }
}
