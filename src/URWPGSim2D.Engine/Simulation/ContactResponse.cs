using URWPGSim2D.Collision.Fish;
using URWPGSim2D.Collision.Motion;

namespace URWPGSim2D.Engine.Simulation;

/// <summary>
/// Resolves one contact as the original's <c>CollisionResponse</c> does, made continuous. First the
/// position correction (<see cref="Separation"/>): a static partner never moves; fish–fish,
/// fish–ball and ball–ball split it in half, a ball hit by a pectoral fin takes 3/4. Then the normal
/// velocities (<see cref="Impulse"/>; tangential parts are kept, fish velocities are taken at the
/// action point):
/// <list type="bullet">
/// <item>fish–ball: the first contact of the pair in a cycle is the original's exchange, masses 0.8
/// and 0.49, e = −0.005·(1 − d/300) (d along the fish axis from its head tip to the action point);
/// the ball takes its new normal speed, the fish's motion is untouched and it turns by the ball's
/// impulse J = 0.49·|Δv_ball| as a heading increment (J·r⊥/6000)·0.01 with the signed lever. A later
/// contact of the same pair in that cycle is a pressing contact, the continuous form of the
/// original's push-out: both move on along the normal at the share-weighted common speed
/// v_ball + s·(v_fish − v_ball), s the ball's share of the correction, and nothing turns. A contact the
/// motion world answers where it finds it, up to a sub-step or a sampling interval after it began
/// (<see cref="Contact.Pressing"/>: a held contact, as a match answers its touching pairs on
/// <see cref="CycleMotion.HeldSubSteps"/> sub-steps, or a pressing one), that is
/// the pair's first in the cycle gets both at once, the
/// exchange then the press, and its correction is shared as those speed changes would have moved the two
/// since (the ball takes (c − v_ball)/(v_fish − v_ball), c the common speed);</item>
/// <item>fish–fish: v_n' = (v_A + v_B + e'·(v_B − v_A))/2 with e' = −0.005·(1 − (d_A + d_B)/600) for
/// the rest of the cycle; on the pair's first contact in a cycle each fish turns by its own J = 0.8·|Δv_n|;</item>
/// <item>fish–obstacle: the fish's normal speed becomes −0.003·(1 − d/300)·v_n; it turns on the
/// first contact (J = 0.8·|Δv_n|); fish–wall and fish–goal block: push-out only, the normal speed
/// into it becomes 0 for the rest of the cycle, no turn;</item>
/// <item>ball–ball: e = 0.005, each ball its own result; ball–wall and ball–goal block: normal
/// speed × −0.001; ball–obstacle: × −0.1.</item>
/// </list>
/// A fish's speed and angular speed (its gear approach) are never changed by a contact: each cycle
/// it swims with its own motion again. The response comes in two parts, as the motion world calls
/// them: the position correction (<see cref="Separate"/>, from <see cref="IContactHandler.OnSeparate"/>),
/// whose corrections of a fish the motion world's wedge policy counts itself (a fish corrected deeper
/// than the time-of-impact tolerance more than <see cref="WedgePolicy.CorrectionsBeforeRejecting"/>
/// times in one cycle is wedged and the motion world rejects its move: back where it started the
/// cycle, at rest), then the velocities (<see cref="Respond"/>). A fish whose move was rejected
/// counts as immovable for the rest of that cycle (its partners take the whole correction, it
/// neither moves nor turns).
/// </summary>
internal sealed class ContactResponse
{
    private const int PartnersPerFish = 8;
    private const int FishKey = 1 << 24;
    private const int StaticKey = 2 << 24;

    private readonly World _world;
    private readonly Separation _separation;
    private readonly int[] _partners;
    private readonly int[] _partnerCount;
    private readonly int[] _partnerCycle;
    private float _ballShare; // the ball's share s of the last fish–ball contact (of its correction at a time of first contact), for its response

    /// <summary>Creates the response for a world.</summary>
    public ContactResponse(World world)
    {
        _world = world;
        _separation = new Separation(world);
        _partners = new int[world.Fish.Length * PartnersPerFish];
        _partnerCount = new int[world.Fish.Length];
        _partnerCycle = new int[world.Fish.Length];
        Array.Fill(_partnerCycle, -1);
    }

    /// <summary>Both parts of the response in order, with no wedge count between them (a contact outside a step); returns its summary kind.</summary>
    public ContactKind Apply(in CandidatePair pair, in Contact hit)
    {
        Separate(pair, hit);
        return Respond(pair, hit);
    }

    /// <summary>The contact's position correction: the pair moved apart by the shares of its kind.</summary>
    public void Separate(in CandidatePair pair, in Contact hit)
    {
        switch (pair.Kind)
        {
            case PairKind.FishFish:
                FishState a = _world.Fish[pair.A], b = _world.Fish[pair.B];
                float shareA = a.MoveRejected == b.MoveRejected ? 0.5f : a.MoveRejected ? 0f : 1f;
                _separation.Apply(pair, hit, shareA, 1f - shareA);
                break;
            case PairKind.FishBall:
                bool pectoral = hit.PartA is FishPart.LeftPectoral or FishPart.RightPectoral;
                FishState fish = _world.Fish[pair.A];
                _ballShare = fish.MoveRejected ? 1f : pectoral ? PhysicsConstants.PectoralBallShare : 0.5f;
                float correction = hit.Pressing && !fish.MoveRejected && !HadContact(fish, pair.B) ? FirstPressShare(fish, _world.Balls[pair.B], hit) : _ballShare;
                _separation.Apply(pair, hit, 1f - correction, correction);
                break;
            case PairKind.BallBall:
                _separation.Apply(pair, hit, 0.5f, 0.5f);
                break;
            default:
                _separation.Apply(pair, hit, 1f, 0f);
                break;
        }
    }

    /// <summary>The contact's velocities and turns, after <see cref="Separate"/>; returns its summary kind.</summary>
    public ContactKind Respond(in CandidatePair pair, in Contact hit)
    {
        switch (pair.Kind)
        {
            case PairKind.FishFish:
                FishFish(pair, hit);
                return ContactKind.FishFish;
            case PairKind.FishBall:
                FishBall(pair, hit);
                return ContactKind.FishBall;
            case PairKind.BallBall:
                BallBall(pair, hit);
                return ContactKind.BallBall;
            case PairKind.FishStatic:
            case PairKind.FishWall:
                return FishStatic(pair, hit);
            default:
                return BallStatic(pair, hit);
        }
    }

    /// <summary>Distance along the fish axis from its head tip back to a point, mm.</summary>
    public static float AxisDistanceFromHead(FishState fish, Vector2 point) =>
        fish.HeadReach - Vector2.Dot(point - fish.Position, fish.Forward);

    /// <summary>The fish–ball restitution e = −0.005·(1 − d/300) at an action point.</summary>
    public static float FishBallRestitution(FishState fish, Vector2 point) =>
        PhysicsConstants.FishBallRestitution * (1f - (AxisDistanceFromHead(fish, point) / PhysicsConstants.RestitutionReach));

    private void FishBall(in CandidatePair pair, in Contact hit)
    {
        FishState fish = _world.Fish[pair.A];
        BallState ball = _world.Balls[pair.B];
        float ballShare = _ballShare;
        Vector2 n = hit.Normal;
        Vector2 lever = hit.Point - fish.Position;
        float vf = NormalSpeed(fish, lever, n);
        float vb = Vector2.Dot(ball.Velocity, n);
        if (vf - vb >= 0f)
        {
            return;
        }

        if (FirstContact(fish, pair.B))
        {
            float e = FishBallRestitution(fish, hit.Point);
            float after = Impulse.Exchange(vb, PhysicsConstants.BallMass, vf, PhysicsConstants.FishMass, e);
            ball.Velocity += (after - vb) * n;
            Turn(fish, lever, -PhysicsConstants.BallMass * (after - vb) * n);
            if (!hit.Pressing || vf - after >= 0f)
            {
                return;
            }

            // Answered where found, the contact began earlier: the pair has pressed on since.
            vb = after;
        }

        float common = vb + (ballShare * (vf - vb));
        ball.Velocity += (common - vb) * n;
        if (!fish.MoveRejected)
        {
            fish.Velocity += (common - vf) * n;
        }
    }

    private void FishFish(in CandidatePair pair, in Contact hit)
    {
        FishState a = _world.Fish[pair.A];
        FishState b = _world.Fish[pair.B];
        Vector2 n = hit.Normal;
        Vector2 ra = hit.Point - a.Position;
        Vector2 rb = hit.Point - b.Position;
        float va = NormalSpeed(a, ra, n);
        float vb = NormalSpeed(b, rb, n);
        if (va - vb >= 0f)
        {
            return;
        }

        float reach = 2f * PhysicsConstants.RestitutionReach;
        float e = PhysicsConstants.FishFishRestitution * (1f - ((AxisDistanceFromHead(a, hit.Point) + AxisDistanceFromHead(b, hit.Point)) / reach));
        // A fish whose move was rejected is immovable: the other one takes its normal speed.
        float afterA = a.MoveRejected ? va : b.MoveRejected ? vb : Impulse.Exchange(va, PhysicsConstants.FishMass, vb, PhysicsConstants.FishMass, e);
        float afterB = b.MoveRejected ? vb : a.MoveRejected ? va : Impulse.Exchange(vb, PhysicsConstants.FishMass, va, PhysicsConstants.FishMass, e);
        bool first = FirstContact(a, FishKey | pair.B);
        if (!a.MoveRejected)
        {
            a.Velocity += (afterA - va) * n;
            if (first)
            {
                Turn(a, ra, PhysicsConstants.FishMass * (afterA - va) * n);
            }
        }

        if (!b.MoveRejected)
        {
            b.Velocity += (afterB - vb) * n;
            if (first)
            {
                Turn(b, rb, PhysicsConstants.FishMass * (afterB - vb) * n);
            }
        }
    }

    private ContactKind FishStatic(in CandidatePair pair, in Contact hit)
    {
        FishState fish = _world.Fish[pair.A];
        bool border = pair.Kind == PairKind.FishWall || _world.Statics[pair.B].IsGoalBlock;
        Vector2 n = hit.Normal;
        Vector2 lever = hit.Point - fish.Position;
        float vn = NormalSpeed(fish, lever, n);
        if (vn < 0f && !fish.MoveRejected)
        {
            float after = border ? 0f : PhysicsConstants.FishObstacleFactor * (1f - (AxisDistanceFromHead(fish, hit.Point) / PhysicsConstants.RestitutionReach)) * vn;
            fish.Velocity += (after - vn) * n;
            if (!border && FirstContact(fish, StaticKey | pair.B))
            {
                Turn(fish, lever, PhysicsConstants.FishMass * (after - vn) * n);
            }
        }

        return border ? ContactKind.FishBorder : ContactKind.FishObstacle;
    }

    private ContactKind BallStatic(in CandidatePair pair, in Contact hit)
    {
        BallState ball = _world.Balls[pair.A];
        bool border = pair.Kind == PairKind.BallWall || _world.Statics[pair.B].IsGoalBlock;
        Vector2 n = hit.Normal;
        float vn = Vector2.Dot(ball.Velocity, n);
        if (vn < 0f)
        {
            float factor = border ? PhysicsConstants.BallWallFactor : PhysicsConstants.BallObstacleFactor;
            ball.Velocity += ((factor * vn) - vn) * n;
        }

        return border ? ContactKind.BallBorder : ContactKind.BallObstacle;
    }

    private void BallBall(in CandidatePair pair, in Contact hit)
    {
        BallState a = _world.Balls[pair.A];
        BallState b = _world.Balls[pair.B];
        Vector2 n = hit.Normal;
        float va = Vector2.Dot(a.Velocity, n);
        float vb = Vector2.Dot(b.Velocity, n);
        if (va - vb >= 0f)
        {
            return;
        }

        float afterA = Impulse.Exchange(va, PhysicsConstants.BallMass, vb, PhysicsConstants.BallMass, PhysicsConstants.BallBallRestitution);
        float afterB = Impulse.Exchange(vb, PhysicsConstants.BallMass, va, PhysicsConstants.BallMass, PhysicsConstants.BallBallRestitution);
        a.Velocity += (afterA - va) * n;
        b.Velocity += (afterB - vb) * n;
    }

    // The fish's velocity along n at the action point (its in-cycle motion, turning included).
    private static float NormalSpeed(FishState fish, Vector2 lever, Vector2 n) =>
        Vector2.Dot(Impulse.PointVelocity(fish.Velocity, fish.AngularVelocity, lever), n);

    // The heading increment of a fish that takes `impulse` at `lever`: a pose change at the contact
    // time, never a change of its angular speed. A wedged fish (its move rejected) does not turn.
    private static void Turn(FishState fish, Vector2 lever, Vector2 impulse)
    {
        if (fish.MoveRejected)
        {
            return;
        }

        float turn = Impulse.HeadingIncrement(lever, impulse);
        if (turn != 0f)
        {
            fish.Heading = Angle.Wrap(fish.Heading + turn);
        }
    }

    // The ball's share of the correction of a fish–ball contact answered where found (a held contact,
    // Contact.Pressing) that is the pair's first in the cycle: what the responses would have done since
    // the time of first contact, to first order. There the exchange gives the ball its new normal
    // speed and leaves the fish's, and the pair, still closing, presses on at the common speed c at
    // once; moving on at c since then, each body is displaced by its change of normal speed times the
    // time since, so the ball takes (c − v_b) / (v_f − v_b) of the overlap (0.81 for a ball at rest
    // against a fish at full speed, against the half it takes at a time of first contact).
    private float FirstPressShare(FishState fish, BallState ball, in Contact hit)
    {
        Vector2 n = hit.Normal;
        float vf = NormalSpeed(fish, hit.Point - fish.Position, n);
        float vb = Vector2.Dot(ball.Velocity, n);
        if (vf - vb >= 0f)
        {
            return _ballShare;
        }

        float after = Impulse.Exchange(vb, PhysicsConstants.BallMass, vf, PhysicsConstants.FishMass, FishBallRestitution(fish, hit.Point));
        float common = vf - after < 0f ? after + (_ballShare * (vf - after)) : after;
        return Math.Clamp((common - vb) / (vf - vb), 0f, 1f);
    }

    /// <summary>Forgets every fish's contacts of the cycle (a match put back to cycle 0 in place counts its cycles again).</summary>
    public void Restart() => Array.Fill(_partnerCycle, -1);

    // Whether the fish had a contact with `partner` in the current cycle already (nothing recorded).
    private bool HadContact(FishState fish, int partner)
    {
        int i = fish.Index;
        if (_partnerCycle[i] != _world.Cycle)
        {
            return false;
        }

        ReadOnlySpan<int> partners = _partners.AsSpan(i * PartnersPerFish, _partnerCount[i]);
        return partners.Contains(partner) || _partnerCount[i] == PartnersPerFish;
    }

    // Whether this is the fish's first contact with `partner` in the current cycle (and records it).
    // More partners in one cycle than the fish can record count as repeated contacts.
    private bool FirstContact(FishState fish, int partner)
    {
        int i = fish.Index;
        if (_partnerCycle[i] != _world.Cycle)
        {
            _partnerCycle[i] = _world.Cycle;
            _partnerCount[i] = 0;
        }

        int start = i * PartnersPerFish;
        int count = _partnerCount[i];
        for (int k = 0; k < count; k++)
        {
            if (_partners[start + k] == partner)
            {
                return false;
            }
        }

        if (count == PartnersPerFish)
        {
            return false;
        }

        _partners[start + count] = partner;
        _partnerCount[i] = count + 1;
        return true;
    }
}
