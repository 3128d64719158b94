using URWPGSim2D.Collision.Shapes;

namespace URWPGSim2D.Collision.Tests.Motion;

/// <summary>
/// A fish's joints turning over a step (<see cref="MotionWorld.SetJointTargets"/>): the tail is
/// swept like any motion, so what it passes through is met when it happens; the joints reach their
/// targets exactly at the end of the step; a rejected move or <see cref="MotionWorld.SetJoints"/> stops the turn.
/// </summary>
public sealed class MotionWorldJointTurnTests
{
    private static readonly FishPart[] Parts = Enum.GetValues<FishPart>();

    [Fact]
    public void TheSwingBoundsHowFarAnyPointOfTheFishTravelsWhileItsJointsTurn()
    {
        // Brute force: every vertex of every leaf, followed through 64 poses of a linear turn; the
        // length of its path never exceeds the swing the motion world plans with, and the bound is
        // not loose by more than a small factor on the worst point.
        var random = new Random(11);
        float tightest = 0f;
        for (int i = 0; i < 200; i++)
        {
            float scale = 0.6f + (float)random.NextDouble();
            var size = new FishSize(160f * scale, 45f * scale, 30f * scale, 88f * scale, 66f * scale, 55f * scale);
            Vector3 from = RandomJoints(random), to = RandomJoints(random);
            if (i % 3 == 0)
            {
                // One joint at a time too, where the bound of that joint alone is tested.
                int only = i % 9 / 3;
                to = from + (only switch { 0 => Vector3.UnitX, 1 => Vector3.UnitY, _ => Vector3.UnitZ } * ((float)random.NextDouble() - 0.5f));
            }

            var pose = new Vector2((float)random.NextDouble() * 100f, (float)random.NextDouble() * 100f);
            float heading = (float)((random.NextDouble() * 2.0 * Math.PI) - Math.PI);
            float swing = Body.Swing(size, to - from);
            float longest = 0f;
            foreach (FishPart part in Parts)
            {
                Vector2[] previous = Leaf(size, pose, heading, from, part);
                var path = new float[previous.Length];
                for (int k = 1; k <= 64; k++)
                {
                    Vector2[] now = Leaf(size, pose, heading, Vector3.Lerp(from, to, k / 64f), part);
                    for (int v = 0; v < now.Length; v++)
                    {
                        path[v] += Vector2.Distance(previous[v], now[v]);
                    }

                    previous = now;
                }

                foreach (float length in path)
                {
                    longest = MathF.Max(longest, length);
                }
            }

            try
            {
                Assert.True(longest <= (swing * 1.0001f) + 1e-3f, $"a point travels {longest} mm, the swing is {swing} mm");
            }
            catch (XunitException e)
            {
                throw RandomCaseException.At(11, i, e);
            }

            if (swing > 1f)
            {
                tightest = MathF.Max(tightest, longest / swing);
            }
        }

        Assert.True(tightest > 0.6f, $"the swing overstates the farthest travel by {1f / tightest:F2}×");
    }

    [Fact]
    public void ATurningTailMeetsWhatItPassesThroughAtItsTimeOfFirstContact()
    {
        // The caudal part swings from one side to the other; a small post stands where it passes
        // the fish's axis: apart at both ends of the turn, met in between.
        var from = new Vector3(0f, 0f, -0.6f);
        var to = new Vector3(0f, 0f, 0.6f);
        var post = new Circle(new Vector2(-289f, 0f), 4f);
        var start = new FishPose(Vector2.Zero, 0f, from.X, from.Y, from.Z);

        // The setting as stated: the post is apart from the fish at both ends, inside it half-way.
        Assert.False(Overlaps(start, from, post));
        Assert.False(Overlaps(start, to, post));
        Assert.True(Overlaps(start, Vector3.Zero, post));

        // Joints set at once: the post is never met (the tail jumps over it).
        var jumped = new MotionWorld();
        BodyId fishJumped = jumped.AddFish(FishSize.Default, start);
        jumped.AddStatic(post);
        jumped.SetJoints(fishJumped, to.X, to.Y, to.Z);
        var none = new RecordingHandler();
        jumped.Step(0.1f, none);
        Assert.Empty(none.Contacts);

        // Joints turned over the step: the first contact comes at the time a brute-force scan of the turn
        // first finds them overlapping, no deeper than the time-of-impact tolerance.
        var world = new MotionWorld();
        BodyId fish = world.AddFish(FishSize.Default, start);
        BodyId postId = world.AddStatic(post);
        world.SetJointTargets(fish, to.X, to.Y, to.Z);
        var handler = new RecordingHandler();
        world.Step(0.1f, handler);
        // (The tail goes on turning into the post after the first contact: the handler pushes the fish away each time.)
        Assert.All(handler.Contacts, c => Assert.Equal(postId, c.BodyB));
        Contact first = handler.Contacts[0];
        Assert.Contains(first.PartA, new FishPart?[] { FishPart.Tail3, FishPart.LeftCaudal, FishPart.RightCaudal });

        const int Scan = 4000;
        int k = 0;
        while (!Overlaps(start, Vector3.Lerp(from, to, k / (float)Scan), post))
        {
            k++;
        }

        double scanned = k / (double)Scan;
        float swing = Body.Swing(FishSize.Default, to - from);
        Assert.InRange(first.Time, scanned - (1.0 / Scan), scanned + (MotionTolerances.TimeOfImpactTolerance / swing));
        Assert.InRange(first.Depth, MotionTolerances.ContactSlop, MotionTolerances.TimeOfImpactTolerance + 0.05f);
    }

    [Fact]
    public void TheJointsTurnLinearlyInTimeAndReachTheirTargetsExactlyAtTheEnd()
    {
        var world = new MotionWorld();
        var from = new Vector3(0.3f, -0.2f, 0.1f);
        var to = new Vector3(-0.25f, 0.4f, -0.5f);
        BodyId fish = world.AddFish(FishSize.Default, new FishPose(Vector2.Zero, 0f, from.X, from.Y, from.Z));
        BodyId ball = world.AddCircle(20f, new Vector2(400f, 0f));
        world.SetVelocity(ball, new Vector2(-4000f, 0f));
        world.SetJointTargets(fish, to.X, to.Y, to.Z);

        // Until the step the fish keeps its joints.
        FishPose before = world.FishPoseOf(fish);
        Assert.Equal(from, new Vector3(before.Joint1, before.Joint2, before.Joint3));

        // The ball meets the head during the step: there the joints are the turn's at that time.
        var seen = new JointsAtContact(fish);
        world.Step(0.1f, seen);
        Assert.True(seen.Time is > 0.0 and < 1.0, $"contact at {seen.Time}");
        Vector3 expected = from + ((to - from) * (float)seen.Time);
        Assert.Equal(expected.X, seen.Joints.X, 1e-6f);
        Assert.Equal(expected.Y, seen.Joints.Y, 1e-6f);
        Assert.Equal(expected.Z, seen.Joints.Z, 1e-6f);
        Assert.Equal(1, world.Events);

        FishPose after = world.FishPoseOf(fish);
        Assert.Equal(to, new Vector3(after.Joint1, after.Joint2, after.Joint3));

        // The turn was for one step: through the next one the joints hold their targets (seen
        // at another contact in the middle of that step, and at its end).
        world.SetPose(ball, new Vector2(400f, 0f), 0f);
        world.SetVelocity(ball, new Vector2(-4000f, 0f));
        var next = new JointsAtContact(fish);
        world.Step(0.1f, next);
        Assert.True(next.Time is > 0.0 and < 1.0, $"contact at {next.Time}");
        Assert.Equal(to, next.Joints);
        FishPose held = world.FishPoseOf(fish);
        Assert.Equal(to, new Vector3(held.Joint1, held.Joint2, held.Joint3));
    }

    [Fact]
    public void AFishTurningWhileItsTailBeatsMeetsAPostWhenABruteForceScanDoes()
    {
        // The fish turns fast about its centre while its tail swings the other way: the tail's
        // path is the sum of both. Random posts near the tail; the first contact against a scan of
        // 4,000 poses of the combined motion (and no contact where the scan finds none).
        var random = new Random(17);
        int met = 0;
        for (int i = 0; i < 200; i++)
        {
            float omega = (float)((random.NextDouble() * 16.0) - 8.0);
            var from = new Vector3(0.3f, 0.3f, 0.5f) * MathF.Sign(omega);
            Vector3 to = -from;
            float angle = (float)(Math.PI + ((random.NextDouble() - 0.5) * 1.6));
            float distance = 230f + (float)(random.NextDouble() * 120.0);
            var post = new Circle(new Vector2(MathF.Cos(angle), MathF.Sin(angle)) * distance, 3f + (float)(random.NextDouble() * 6.0));
            var start = new FishPose(Vector2.Zero, 0f, from.X, from.Y, from.Z);
            if (Overlaps(start, from, post))
            {
                continue;
            }

            var world = new MotionWorld();
            BodyId fish = world.AddFish(FishSize.Default, start);
            world.AddStatic(post);
            world.SetVelocity(fish, Vector2.Zero, omega);
            world.SetJointTargets(fish, to.X, to.Y, to.Z);
            var handler = new RecordingHandler();
            world.Step(0.1f, handler);

            const int Scan = 4000;
            int k = 0;
            while (k <= Scan && !Overlaps(new FishPose(Vector2.Zero, omega * 0.1f * k / Scan, 0f, 0f, 0f), Vector3.Lerp(from, to, k / (float)Scan), post))
            {
                k++;
            }

            try
            {
                if (k > Scan)
                {
                    Assert.Empty(handler.Contacts);
                    continue;
                }

                // Met no earlier than the scan finds them overlapping, shallow (a grazing contact is
                // answered where a sample finds it no deeper than the tolerance), and before the
                // pair can move more than its sampling limit past the first contact.
                met++;
                Assert.NotEmpty(handler.Contacts);
                Contact first = handler.Contacts[0];
                double scanned = k / (double)Scan;
                float travel = Body.Swing(FishSize.Default, to - from) + (MathF.Abs(omega) * 0.1f * 350f);
                float limit = 0.5f * ((2f * 0.089964f * FishSize.Default.Joint3) + (2f * post.Radius));
                Assert.InRange(first.Time, scanned - (1.0 / Scan), scanned + (limit / travel) + (1.0 / Scan));
                Assert.InRange(first.Depth, MotionTolerances.ContactSlop, MotionTolerances.TimeOfImpactTolerance + 0.05f);
            }
            catch (XunitException e)
            {
                throw RandomCaseException.At(17, i, e);
            }
        }

        Assert.True(met > 30, $"only {met} posts met");
    }

    [Fact]
    public void TheSweptCircleHoldsEveryLeafOfATurningFishWithABeatingTailThroughTheStep()
    {
        // Brute force: 64 poses of the step, every leaf vertex inside the swept circle the step planned.
        var random = new Random(29);
        float tightest = 0f;
        for (int i = 0; i < 200; i++)
        {
            var world = new MotionWorld();
            Vector3 from = RandomJoints(random), to = RandomJoints(random);
            float heading = (float)(random.NextDouble() * 6.0);
            var velocity = new Vector2((float)(random.NextDouble() * 600.0) - 300f, (float)(random.NextDouble() * 600.0) - 300f);
            float omega = (float)((random.NextDouble() * 24.0) - 12.0);
            BodyId fish = world.AddFish(FishSize.Default, new FishPose(Vector2.Zero, heading, from.X, from.Y, from.Z));
            world.SetVelocity(fish, velocity, omega);
            world.SetJointTargets(fish, to.X, to.Y, to.Z);
            world.Step(0.1f, new RecordingHandler());
            Disc swept = world.SweptCircleOf(fish);
            for (int k = 0; k <= 64; k++)
            {
                float t = k / 64f;
                var pose = new FishPose(velocity * 0.1f * t, heading + (omega * 0.1f * t), 0f, 0f, 0f);
                foreach (FishPart part in Parts)
                {
                    foreach (Vector2 v in Leaf(FishSize.Default, pose.Position, pose.Heading, Vector3.Lerp(from, to, t), part))
                    {
                        float reach = Vector2.Distance(v, swept.Center);
                        tightest = MathF.Max(tightest, reach / swept.Radius);
                        Assert.True(reach <= swept.Radius + 1e-3f, $"case {i}: a vertex of {part} at time {t} lies {reach} mm from the swept circle's centre, radius {swept.Radius}");
                    }
                }
            }
        }

        Assert.True(tightest > 0.7f, $"the swept circle is {1f / tightest:F2} times the farthest vertex's distance at best");
    }

    [Fact]
    public void TurningFishGiveTheSameContactsOnOneAndOnTwoThreads()
    {
        static List<Contact> Run(int threads)
        {
            var world = new MotionWorld { Threads = threads, MinimumMoversForThreads = 1 };
            world.AddWalls(new Field(3000f, 2000f, goalBlocks: false));
            var random = new Random(23);
            var fish = new List<BodyId>();
            for (int i = 0; i < 24; i++)
            {
                var at = new Vector2((i % 6 * 450f) - 1150f, (i / 6 * 420f) - 650f);
                BodyId f = world.AddFish(FishSize.Default, new FishPose(at, (float)(random.NextDouble() * 6.0), 0f, 0f, 0f));
                world.SetVelocity(f, new Vector2((float)(random.NextDouble() * 600.0) - 300f, (float)(random.NextDouble() * 600.0) - 300f), (float)(random.NextDouble() * 4.0) - 2f);
                fish.Add(f);
                BodyId ball = world.AddCircle(30f, at + new Vector2(200f, 190f));
                world.SetVelocity(ball, new Vector2((float)(random.NextDouble() * 2000.0) - 1000f, (float)(random.NextDouble() * 2000.0) - 1000f));
            }

            var handler = new RecordingHandler(0.3f);
            int chunks = 0;
            for (int step = 0; step < 30; step++)
            {
                float phase = step * 0.9f;
                foreach (BodyId f in fish)
                {
                    world.SetJointTargets(f, 0.4f * MathF.Sin(phase), 0.5f * MathF.Sin(phase + 1f), 0.6f * MathF.Sin(phase + 2f));
                }

                world.Step(0.1f, handler);
                chunks = Math.Max(chunks, world.Chunks);
            }

            Assert.Equal(threads, chunks);
            return handler.Contacts;
        }

        List<Contact> one = Run(1), two = Run(2);
        Assert.True(one.Count > 50, $"only {one.Count} contacts");
        Assert.Equal(one.Count, two.Count);
        for (int i = 0; i < one.Count; i++)
        {
            Assert.Equal(one[i].Time, two[i].Time);
            Assert.Equal(one[i].Result, two[i].Result);
            Assert.Equal(one[i].BodyA.Index, two[i].BodyA.Index);
            Assert.Equal(one[i].BodyB.Index, two[i].BodyB.Index);
        }
    }

    [Fact]
    public void TargetsStaySetWhenSettleRejectsAMoveBeforeTheStep()
    {
        var world = new MotionWorld();
        BodyId fish = world.AddFish(FishSize.Default, new FishPose(Vector2.Zero, 0f, 0f, 0f, 0f));
        BodyId ball = world.AddCircle(30f, new Vector2(600f, 0f));
        world.Step(0.1f, new RecordingHandler());

        // Placed inside the ball between steps, then targets; Settle rejects the move.
        world.SetPose(fish, new Vector2(520f, 0f), 0f);
        world.SetJointTargets(fish, 0.3f, 0.3f, 0.3f);
        var rejecting = new RejectOnFirstContact();
        world.Settle(rejecting);
        Assert.Equal([fish], rejecting.Rejected);

        world.Step(0.1f, new RecordingHandler());
        FishPose pose = world.FishPoseOf(fish);
        Assert.Equal(new Vector3(0.3f, 0.3f, 0.3f), new Vector3(pose.Joint1, pose.Joint2, pose.Joint3));
        Assert.Equal(new Vector2(600f, 0f), world.PositionOf(ball));
    }

    [Fact]
    public void SetJointsOrARejectedMoveStopsTheTurn()
    {
        // Set at once after the targets: the joints hold the angles set at once.
        var world = new MotionWorld();
        BodyId fish = world.AddFish(FishSize.Default, new FishPose(Vector2.Zero, 0f, 0.1f, 0.1f, 0.1f));
        world.SetJointTargets(fish, 0.5f, 0.5f, 0.5f);
        world.SetJoints(fish, -0.2f, -0.2f, -0.2f);
        world.Step(0.1f, new RecordingHandler());
        Assert.Equal(new FishPose(Vector2.Zero, 0f, -0.2f, -0.2f, -0.2f), world.FishPoseOf(fish));

        // Rejected at a contact: back to the joints the step began with, and they stay there.
        var rejecting = new MotionWorld();
        var start = new FishPose(Vector2.Zero, 0f, 0f, 0f, -0.6f);
        BodyId wedged = rejecting.AddFish(FishSize.Default, start);
        rejecting.AddStatic(new Circle(new Vector2(-289f, 0f), 4f));
        rejecting.SetJointTargets(wedged, 0f, 0f, 0.6f);
        var handler = new RejectOnFirstContact();
        rejecting.Step(0.1f, handler);
        Assert.Equal([wedged], handler.Rejected);
        Assert.Equal(start, rejecting.FishPoseOf(wedged));
    }

    [Fact]
    public void ItIsRefusedByNameForAnythingButAFishFiniteAnglesBetweenSteps()
    {
        var world = new MotionWorld();
        BodyId ball = world.AddCircle(10f, new Vector2(500f, 0f));
        BodyId fish = world.AddFish(FishSize.Default, new FishPose(Vector2.Zero, 0f, 0f, 0f, 0f));
        Assert.Contains("not a Fish", Assert.Throws<ArgumentException>(() => world.SetJointTargets(ball, 0f, 0f, 0f)).Message);
        Assert.Equal("fish", Assert.Throws<ArgumentException>(() => world.SetJointTargets(default, 0f, 0f, 0f)).ParamName);
        var nan = Assert.Throws<ArgumentException>(() => world.SetJointTargets(fish, 0f, float.NaN, 0f));
        Assert.Equal("joint2", nan.ParamName);

        world.SetVelocity(ball, new Vector2(-4000f, 0f));
        var inStep = new TargetsInStep(fish);
        world.Step(0.1f, inStep);
        Assert.NotNull(inStep.Refused);
        Assert.Equal("fish", inStep.Refused!.ParamName);
        Assert.Contains("only between steps", inStep.Refused.Message, StringComparison.Ordinal);
    }

    private static Vector3 RandomJoints(Random random) =>
        new((float)((random.NextDouble() * 1.6) - 0.8), (float)((random.NextDouble() * 1.6) - 0.8), (float)((random.NextDouble() * 1.6) - 0.8));

    private static Vector2[] Leaf(FishSize size, Vector2 position, float heading, Vector3 joints, FishPart part) =>
        new FishModel(size, new FishPose(position, heading, joints.X, joints.Y, joints.Z)).GetLeaf(part).ToArray();

    // Whether a default fish at the pose, with these joints, overlaps the circle (the motion world's own exact test).
    private static bool Overlaps(FishPose pose, Vector3 joints, Circle circle)
    {
        var world = new MotionWorld();
        BodyId fish = world.AddFish(FishSize.Default, new FishPose(pose.Position, pose.Heading, joints.X, joints.Y, joints.Z));
        BodyId other = world.AddStatic(circle);
        return world.Detect(fish, other).Depth > MotionTolerances.ContactSlop;
    }

    // Records the fish's joints at the first contact.
    private sealed class JointsAtContact(BodyId fish) : IContactHandler
    {
        public double Time { get; private set; } = -1.0;

        public Vector3 Joints { get; private set; }

        public void OnContact(MotionWorld world, in Contact contact)
        {
            if (Time < 0.0)
            {
                Time = contact.Time;
                FishPose pose = world.FishPoseOf(fish);
                Joints = new Vector3(pose.Joint1, pose.Joint2, pose.Joint3);
            }

            BodyId ball = contact.BodyA == fish ? contact.BodyB : contact.BodyA;
            world.SetVelocity(ball, Vector2.Zero);
            world.SetPose(ball, world.PositionOf(ball) + (Vector2.Normalize(world.PositionOf(ball)) * (contact.Depth + 1f)), 0f);
        }

        public void OnMoveRejected(MotionWorld world, BodyId body)
        {
        }
    }

    // Rejects the moving body's move at its first contact.
    private sealed class RejectOnFirstContact : IContactHandler
    {
        public List<BodyId> Rejected { get; } = [];

        public void OnContact(MotionWorld world, in Contact contact)
        {
            if (!world.WasRejected(contact.BodyA))
            {
                world.RejectMove(contact.BodyA);
            }
        }

        public void OnMoveRejected(MotionWorld world, BodyId body) => Rejected.Add(body);
    }

    // Tries to set joint targets from a handler.
    private sealed class TargetsInStep(BodyId fish) : IContactHandler
    {
        public ArgumentException? Refused { get; private set; }

        public void OnContact(MotionWorld world, in Contact contact)
        {
            try
            {
                world.SetJointTargets(fish, 0.1f, 0.1f, 0.1f);
            }
            catch (ArgumentException e)
            {
                Refused ??= e;
            }

            BodyId ball = contact.BodyA == fish ? contact.BodyB : contact.BodyA;
            world.SetVelocity(ball, Vector2.Zero);
            world.SetPose(ball, world.PositionOf(ball) + new Vector2(contact.Depth + 1f, 0f), 0f);
        }

        public void OnMoveRejected(MotionWorld world, BodyId body)
        {
        }
    }
}
