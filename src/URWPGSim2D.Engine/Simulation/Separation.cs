using URWPGSim2D.Collision.Fish;
using URWPGSim2D.Collision.Shapes;
using URWPGSim2D.Collision.Motion;

namespace URWPGSim2D.Engine.Simulation;

/// <summary>
/// Position correction that always ends apart. The deepest leaf's MTV is tried first; a fish is
/// a compound, non-convex body (a body can sit in the bend of another fish's tail), so that MTV
/// alone may leave other leaves overlapping. Then the pair is pushed along the sum of all its leaf
/// MTVs (walls: along each new MTV in turn) by the least distance that frees it, found by doubling
/// and bisection. Shares say which part of the push each body takes (0 for a static one).
/// </summary>
internal sealed class Separation(World world)
{
    private const int MaxSearchSteps = 24;
    private readonly FishContact[] _contacts = new FishContact[FishCollision.MaxContactsWithFish]; // every leaf pair of two fish

    /// <summary>Moves A and B of <paramref name="pair"/> apart; the first move is the contact's own MTV.</summary>
    public void Apply(in CandidatePair pair, in Contact hit, float shareA, float shareB)
    {
        Vector2 mtv = hit.Mtv * ((hit.Depth + PhysicsConstants.SeparationMargin) / MathF.Max(hit.Depth, 1e-12f));
        Offset(pair, mtv * shareA, -mtv * shareB);
        bool wall = pair.Kind is PairKind.FishWall or PairKind.BallWall;
        for (int attempt = 0; attempt < 4; attempt++)
        {
            Contact now = world.Detect(pair);
            if (now.Depth <= MotionTolerances.ContactSlop)
            {
                return;
            }

            if (wall)
            {
                Vector2 m = now.Mtv * ((now.Depth + PhysicsConstants.SeparationMargin) / now.Depth);
                Offset(pair, m, Vector2.Zero);
                continue;
            }

            Vector2 direction = CombinedDirection(pair, now.Normal);
            Search(pair, direction * shareA, -direction * shareB, now.Depth);
        }
    }

    private Vector2 CombinedDirection(in CandidatePair pair, Vector2 fallback)
    {
        int n = pair.Kind is PairKind.FishFish or PairKind.FishBall or PairKind.FishStatic ? world.DetectLeaves(pair, _contacts) : 0;
        Vector2 sum = Vector2.Zero;
        for (int i = 0; i < n; i++)
        {
            sum += new Vector2(_contacts[i].Result.MinimumTranslationVector.X, _contacts[i].Result.MinimumTranslationVector.Z);
        }

        return sum.LengthSquared() > 1e-12f ? Vector2.Normalize(sum) : fallback;
    }

    // Least s (to 0.05 mm) with the pair apart after moving A by s·stepA and B by s·stepB.
    private void Search(in CandidatePair pair, Vector2 stepA, Vector2 stepB, float depth)
    {
        float lo = 0f;
        float hi = MathF.Max(depth, 1f);
        float applied = 0f;
        int i = 0;
        while (i++ < MaxSearchSteps)
        {
            Offset(pair, stepA * (hi - applied), stepB * (hi - applied));
            applied = hi;
            if (world.Detect(pair).Depth <= MotionTolerances.ContactSlop)
            {
                break;
            }

            lo = hi;
            hi *= 2f;
        }

        while (i++ < MaxSearchSteps && hi - lo > 0.05f)
        {
            float mid = 0.5f * (lo + hi);
            Offset(pair, stepA * (mid - applied), stepB * (mid - applied));
            applied = mid;
            if (world.Detect(pair).Depth <= MotionTolerances.ContactSlop)
            {
                hi = mid;
            }
            else
            {
                lo = mid;
            }
        }

        float final = hi + PhysicsConstants.SeparationMargin;
        Offset(pair, stepA * (final - applied), stepB * (final - applied));
    }

    private void Offset(in CandidatePair pair, Vector2 a, Vector2 b)
    {
        switch (pair.Kind)
        {
            case PairKind.FishFish:
                MoveFish(world.Fish[pair.A], a);
                MoveFish(world.Fish[pair.B], b);
                break;
            case PairKind.FishBall:
                MoveFish(world.Fish[pair.A], a);
                MoveBall(world.Balls[pair.B], b);
                break;
            case PairKind.BallBall:
                MoveBall(world.Balls[pair.A], a);
                MoveBall(world.Balls[pair.B], b);
                break;
            case PairKind.FishStatic:
            case PairKind.FishWall:
                MoveFish(world.Fish[pair.A], a);
                break;
            default:
                MoveBall(world.Balls[pair.A], a);
                break;
        }
    }

    private static void MoveFish(FishState fish, Vector2 offset)
    {
        if (offset == Vector2.Zero)
        {
            return;
        }

        fish.Position += offset;
        fish.NoiseVelocity = Vector2.Zero;
        fish.NoiseAngularVelocity = 0f;
    }

    private static void MoveBall(BallState ball, Vector2 offset)
    {
        ball.Position += offset;
        ball.NoiseVelocity = Vector2.Zero;
    }
}
