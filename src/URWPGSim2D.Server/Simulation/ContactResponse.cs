using System;
using System.Numerics;
using URWPGSim2D.Collision.Fish;

namespace URWPGSim2D.Server.Simulation;

/// <summary>
/// Resolves one contact: position correction from the MTV, then the velocity impulse.
/// Shares of the MTV: a static partner (obstacle, goal block, wall) never moves, the mover takes
/// all of it; fish–fish, fish–ball and ball–ball split it in half, except that a ball hit by a
/// pectoral fin takes 3/4. Restitution: fish–ball 0.995 − d/300 (d = distance along the fish axis
/// from the head tip to the action point), fish–fish and ball–ball 0.005, ball–wall and
/// ball–goal block 0.001, ball–obstacle 0.1, fish–obstacle 0.003·(1 − d/300), fish–wall and
/// fish–goal block 0 (the fish stops moving into it); all clamped to [0, 1]. Masses 0.8 (fish) and
/// 0.49 (ball), fish inertia 6000.
/// </summary>
internal static class ContactResponse
{
    private const float InvFishMass = 1f / PhysicsConstants.FishMass;
    private const float InvBallMass = 1f / PhysicsConstants.BallMass;
    private const float InvFishInertia = 1f / PhysicsConstants.FishInertia;

    /// <summary>Applies the contact and returns its summary kind.</summary>
    public static ContactKind Apply(World world, in CandidatePair pair, in Hit hit)
    {
        Vector2 correction = hit.Mtv * ((hit.Depth + PhysicsConstants.SeparationMargin) / MathF.Max(hit.Depth, 1e-12f));
        Vector2 n = hit.Normal;
        switch (pair.Kind)
        {
            case PairKind.FishFish:
            {
                FishState a = world.Fish[pair.A];
                FishState b = world.Fish[pair.B];
                Move(a, correction * 0.5f);
                Move(b, correction * -0.5f);
                FishFish(a, b, n, hit.Point);
                return ContactKind.FishFish;
            }

            case PairKind.FishBall:
            {
                FishState a = world.Fish[pair.A];
                BallState b = world.Balls[pair.B];
                bool pectoral = hit.PartA == (sbyte)FishPart.LeftPectoral || hit.PartA == (sbyte)FishPart.RightPectoral;
                float ballShare = pectoral ? 0.75f : 0.5f;
                Move(a, correction * (1f - ballShare));
                b.Position -= correction * ballShare;
                b.NoiseVelocity = Vector2.Zero;
                float e = Math.Clamp(0.995f - (AxisDistanceFromHead(a, hit.Point) / 300f), 0f, 1f);
                Vector2 ra = hit.Point - a.Position;
                float j = Impulse.Magnitude(n, e, a.Velocity, a.AngularVelocity, ra, InvFishMass, InvFishInertia, b.Velocity, 0f, Vector2.Zero, InvBallMass, 0f);
                Push(a, ra, n * j);
                b.Velocity -= n * (j * InvBallMass);
                return ContactKind.FishBall;
            }

            case PairKind.BallBall:
            {
                BallState a = world.Balls[pair.A];
                BallState b = world.Balls[pair.B];
                a.Position += correction * 0.5f;
                b.Position -= correction * 0.5f;
                a.NoiseVelocity = Vector2.Zero;
                b.NoiseVelocity = Vector2.Zero;
                float j = Impulse.Magnitude(n, PhysicsConstants.MovingPairRestitution, a.Velocity, 0f, Vector2.Zero, InvBallMass, 0f, b.Velocity, 0f, Vector2.Zero, InvBallMass, 0f);
                a.Velocity += n * (j * InvBallMass);
                b.Velocity -= n * (j * InvBallMass);
                return ContactKind.BallBall;
            }

            case PairKind.FishStatic:
            case PairKind.FishWall:
            {
                FishState a = world.Fish[pair.A];
                bool border = pair.Kind == PairKind.FishWall || world.Statics[pair.B].IsGoalBlock;
                Move(a, correction);
                float e = border ? 0f : Math.Clamp(0.003f * (1f - (AxisDistanceFromHead(a, hit.Point) / 300f)), 0f, 1f);
                Vector2 ra = hit.Point - a.Position;
                float j = Impulse.Magnitude(n, e, a.Velocity, a.AngularVelocity, ra, InvFishMass, InvFishInertia, Vector2.Zero, 0f, Vector2.Zero, 0f, 0f);
                Push(a, ra, n * j);
                return border ? ContactKind.FishBorder : ContactKind.FishObstacle;
            }

            default:
            {
                BallState a = world.Balls[pair.A];
                bool border = pair.Kind == PairKind.BallWall || world.Statics[pair.B].IsGoalBlock;
                a.Position += correction;
                a.NoiseVelocity = Vector2.Zero;
                float e = border ? PhysicsConstants.BallWallRestitution : PhysicsConstants.BallObstacleRestitution;
                float j = Impulse.Magnitude(n, e, a.Velocity, 0f, Vector2.Zero, InvBallMass, 0f, Vector2.Zero, 0f, Vector2.Zero, 0f, 0f);
                a.Velocity += n * (j * InvBallMass);
                return border ? ContactKind.BallBorder : ContactKind.BallObstacle;
            }
        }
    }

    /// <summary>Distance along the fish axis from its head tip back to a point, mm.</summary>
    public static float AxisDistanceFromHead(FishState fish, Vector2 point) =>
        fish.HeadReach - Vector2.Dot(point - fish.Position, fish.Forward);

    private static void FishFish(FishState a, FishState b, Vector2 n, Vector2 point)
    {
        Vector2 ra = point - a.Position;
        Vector2 rb = point - b.Position;
        float j = Impulse.Magnitude(n, PhysicsConstants.MovingPairRestitution, a.Velocity, a.AngularVelocity, ra, InvFishMass, InvFishInertia, b.Velocity, b.AngularVelocity, rb, InvFishMass, InvFishInertia);
        Push(a, ra, n * j);
        Push(b, rb, n * -j);
    }

    private static void Push(FishState fish, Vector2 lever, Vector2 impulse)
    {
        fish.Velocity += impulse * InvFishMass;
        fish.AngularVelocity += Impulse.Cross(lever, impulse) * InvFishInertia;
        fish.Touched = true;
    }

    private static void Move(FishState fish, Vector2 offset)
    {
        fish.Position += offset;
        fish.NoiseVelocity = Vector2.Zero;
        fish.NoiseAngularVelocity = 0f;
        fish.Touched = true;
        fish.SyncModel();
    }
}
