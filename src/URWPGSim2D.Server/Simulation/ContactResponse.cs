using System;
using System.Numerics;
using URWPGSim2D.Collision.Fish;

namespace URWPGSim2D.Server.Simulation;

/// <summary>
/// Resolves one contact: position correction (<see cref="Separation"/>), then the velocity
/// impulse (<see cref="Impulse"/>). Shares of the correction: a static partner (obstacle, goal
/// block, wall) never moves, the mover takes all of it; fish–fish, fish–ball and ball–ball split it
/// in half, except that a ball hit by a pectoral fin takes 3/4. Restitution: fish–ball
/// 0.995 − d/300 (d = distance along the fish axis from the head tip to the action point),
/// fish–fish and ball–ball 0.005, ball–wall and ball–goal block 0.001, ball–obstacle 0.1,
/// fish–obstacle 0.003·(1 − d/300), fish–wall and fish–goal block 0 (the fish stops moving into
/// it); all clamped to [0, 1]. Masses 0.8 (fish) and 0.49 (ball), fish inertia 6000. A fish
/// corrected more than <see cref="PhysicsConstants.MaximumCorrectionsPerFish"/> times in one cycle
/// is wedged: <see cref="FishState.Freeze"/> rejects its move, and from then on in that cycle it
/// counts as immovable (its partners take the whole correction and it takes no impulse).
/// </summary>
internal sealed class ContactResponse(World world)
{
    private const float InvFishMass = 1f / PhysicsConstants.FishMass;
    private const float InvBallMass = 1f / PhysicsConstants.BallMass;
    private const float InvFishInertia = 1f / PhysicsConstants.FishInertia;

    private readonly Separation _separation = new(world);

    /// <summary>Applies the contact and returns its summary kind.</summary>
    public ContactKind Apply(in CandidatePair pair, in Hit hit)
    {
        Vector2 n = hit.Normal;
        switch (pair.Kind)
        {
            case PairKind.FishFish:
            {
                FishState a = world.Fish[pair.A];
                FishState b = world.Fish[pair.B];
                float shareA = a.Frozen == b.Frozen ? 0.5f : a.Frozen ? 0f : 1f;
                _separation.Apply(pair, hit, shareA, 1f - shareA);
                Vector2 ra = hit.Point - a.Position;
                Vector2 rb = hit.Point - b.Position;
                float j = Impulse.Magnitude(n, PhysicsConstants.MovingPairRestitution, a.Velocity, a.AngularVelocity, ra, InverseMass(a), InverseInertia(a), b.Velocity, b.AngularVelocity, rb, InverseMass(b), InverseInertia(b));
                Push(a, ra, n * j);
                Push(b, rb, n * -j);
                Count(a);
                Count(b);
                return ContactKind.FishFish;
            }

            case PairKind.FishBall:
            {
                FishState a = world.Fish[pair.A];
                BallState b = world.Balls[pair.B];
                bool pectoral = hit.PartA == (sbyte)FishPart.LeftPectoral || hit.PartA == (sbyte)FishPart.RightPectoral;
                float ballShare = a.Frozen ? 1f : pectoral ? 0.75f : 0.5f;
                _separation.Apply(pair, hit, 1f - ballShare, ballShare);
                float e = Math.Clamp(0.995f - (AxisDistanceFromHead(a, hit.Point) / 300f), 0f, 1f);
                Vector2 ra = hit.Point - a.Position;
                float j = Impulse.Magnitude(n, e, a.Velocity, a.AngularVelocity, ra, InverseMass(a), InverseInertia(a), b.Velocity, 0f, Vector2.Zero, InvBallMass, 0f);
                Push(a, ra, n * j);
                b.Velocity -= n * (j * InvBallMass);
                Count(a);
                return ContactKind.FishBall;
            }

            case PairKind.BallBall:
            {
                BallState a = world.Balls[pair.A];
                BallState b = world.Balls[pair.B];
                _separation.Apply(pair, hit, 0.5f, 0.5f);
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
                _separation.Apply(pair, hit, 1f, 0f);
                float e = border ? 0f : Math.Clamp(0.003f * (1f - (AxisDistanceFromHead(a, hit.Point) / 300f)), 0f, 1f);
                Vector2 ra = hit.Point - a.Position;
                float j = Impulse.Magnitude(n, e, a.Velocity, a.AngularVelocity, ra, InverseMass(a), InverseInertia(a), Vector2.Zero, 0f, Vector2.Zero, 0f, 0f);
                Push(a, ra, n * j);
                Count(a);
                return border ? ContactKind.FishBorder : ContactKind.FishObstacle;
            }

            default:
            {
                BallState a = world.Balls[pair.A];
                bool border = pair.Kind == PairKind.BallWall || world.Statics[pair.B].IsGoalBlock;
                _separation.Apply(pair, hit, 1f, 0f);
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

    private static float InverseMass(FishState fish) => fish.Frozen ? 0f : InvFishMass;

    private static float InverseInertia(FishState fish) => fish.Frozen ? 0f : InvFishInertia;

    private static void Push(FishState fish, Vector2 lever, Vector2 impulse)
    {
        fish.Velocity += impulse * InverseMass(fish);
        fish.AngularVelocity += Impulse.Cross(lever, impulse) * InverseInertia(fish);
    }

    // A fish that keeps needing corrections in one cycle is wedged: reject its move for this cycle.
    private static void Count(FishState fish)
    {
        if (++fish.Corrections > PhysicsConstants.MaximumCorrectionsPerFish && !fish.Frozen)
        {
            fish.Freeze();
        }
    }
}
