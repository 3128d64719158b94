namespace URWPGSim2D.Collision.Tests.Motion;

/// <summary>
/// The motion world's one wedge policy (<see cref="MotionWorld.Wedging"/>): the corrections a response
/// reports (<see cref="MotionWorld.CountCorrection"/>) are counted per body and step against the
/// policy's allowance, the first deep one past it rejects the move; the events before a body's
/// contacts are left to the end of the step are the policy's too.
/// </summary>
public sealed class MotionWorldWedgePolicyTests
{
    [Fact]
    public void TheFirstDeepCorrectionPastTheAllowanceRejectsTheMoveOnce()
    {
        // Ball a is thrown 50 mm into ball b between steps; settling reports the contact and the
        // response counts twelve corrections of a for it.
        var (world, a, _) = JumpedInto(overlap: 50f);
        var handler = new CountingHandler(a, perContact: 12);
        world.Settle(handler);

        // Default allowance 8: the ninth rejects, the rest find it rejected already.
        Assert.Equal(8, new WedgePolicy().CorrectionsBeforeRejecting);
        bool[] expected = [false, false, false, false, false, false, false, false, true, false, false, false];
        Assert.Equal(expected, handler.Verdicts.GetRange(0, 12));
        Assert.Equal([a], handler.Rejected);
        Assert.True(world.WasRejected(a));

        // Rejected as RejectMove rejects: back where the last step began (its start, 0,0), at rest.
        Assert.Equal(Vector2.Zero, world.PositionOf(a));
        Assert.Equal(Vector2.Zero, world.VelocityOf(a));
    }

    [Fact]
    public void ShallowCorrectionsAreNotCounted()
    {
        // 0.2 mm deep: within the time-of-impact tolerance (0.25 mm), a correction at a refined time of first contact.
        var (world, a, _) = JumpedInto(overlap: 0.2f);
        var handler = new CountingHandler(a, perContact: 30);
        world.Settle(handler);

        Assert.True(handler.Contacts > 0, "settling reported no contact");
        Assert.All(handler.Verdicts, v => Assert.False(v));
        Assert.Empty(handler.Rejected);
        Assert.False(world.WasRejected(a));
    }

    [Fact]
    public void TheAllowanceIsThePolicys()
    {
        var (world, a, _) = JumpedInto(overlap: 50f);
        world.Wedging = new WedgePolicy { CorrectionsBeforeRejecting = 2 };
        var handler = new CountingHandler(a, perContact: 4);
        world.Settle(handler);
        Assert.Equal([false, false, true, false], handler.Verdicts.GetRange(0, 4));

        var (strict, b, _) = JumpedInto(overlap: 50f);
        strict.Wedging = new WedgePolicy { CorrectionsBeforeRejecting = 0 };
        var first = new CountingHandler(b, perContact: 1);
        strict.Settle(first);
        Assert.True(first.Verdicts[0]);
    }

    [Fact]
    public void TheCountRunsThroughSettlesAndStartsAgainWithAStep()
    {
        // Six corrections in one settle, six in the next: the ninth of the step rejects.
        var (world, a, b) = JumpedInto(overlap: 50f);
        var handler = new CountingHandler(a, perContact: 6);
        world.Settle(handler);
        world.SetPose(a, world.PositionOf(b) - new Vector2(50f, 0f), 0f);
        world.Settle(handler);
        Assert.Equal([false, false, false, false, false, false, false, false, true, false, false, false], handler.Verdicts.GetRange(0, 12));

        // A step between the two settles starts the count again: twelve corrections, none rejects.
        var (other, c, d) = JumpedInto(overlap: 50f);
        var again = new CountingHandler(c, perContact: 6);
        other.Settle(again);
        other.Step(0.1f, again);
        other.SetPose(c, other.PositionOf(d) - new Vector2(50f, 0f), 0f);
        other.Settle(again);
        Assert.True(again.Verdicts.Count >= 12, $"{again.Verdicts.Count} corrections");
        Assert.All(again.Verdicts, v => Assert.False(v));
        Assert.False(other.WasRejected(c));
    }

    [Fact]
    public void TheEventsThatMakeABarWedgedAreThePolicys()
    {
        int Most(WedgePolicy? policy)
        {
            var world = MotionWorldWedgeTests.BarInSlot(out BodyId body);
            if (policy is not null)
            {
                world.Wedging = policy;
            }

            var handler = new RecordingHandler { Record = false };
            int most = 0;
            for (int step = 0; step < 30; step++)
            {
                world.SetVelocity(body, Vector2.Zero, 3f);
                world.Step(0.1f, handler);
                most = Math.Max(most, world.Events);
                Assert.True(world.MeasureOverlap() <= 0.5f, $"step {step}: measured {world.MeasureOverlap()} mm");
            }

            return most;
        }

        // The bar is found wedged by its events in a row at one time (2 by default); with that rule
        // off (a large count) it takes many events a step, and the events-per-step rule bounds them.
        int usual = Most(null);
        int many = Most(new WedgePolicy { EventsInPlaceBeforeDeferring = 1000 });
        int strict = Most(new WedgePolicy { EventsInPlaceBeforeDeferring = 1000, EventsBeforeDeferring = 4 });
        Assert.True(many > usual, $"in place off {many} events, default {usual}");
        Assert.True(many <= 16 + 2, $"in place off {many} events in one step");
        Assert.True(strict <= 4 + 2, $"{strict} events in one step");
        Assert.True(strict < many, $"16 events before deferring: {many}, 4: {strict}");
    }

    [Fact]
    public void BadPoliciesAndCallsAreRefusedByNameAndNothingCountsBetweenSteps()
    {
        var events = Assert.Throws<ArgumentException>(() => new WedgePolicy { EventsBeforeDeferring = 0 });
        Assert.Equal("eventsBeforeDeferring", events.ParamName);
        Assert.Contains("got 0", events.Message, StringComparison.Ordinal);
        Assert.Equal("eventsInPlaceBeforeDeferring", Assert.Throws<ArgumentException>(() => new WedgePolicy { EventsInPlaceBeforeDeferring = -1 }).ParamName);
        var corrections = Assert.Throws<ArgumentException>(() => new WedgePolicy { CorrectionsBeforeRejecting = -3 });
        Assert.Equal("correctionsBeforeRejecting", corrections.ParamName);
        Assert.Contains("got -3", corrections.Message, StringComparison.Ordinal);

        // A ball 10 mm into a static box: settling reports their contact to a handler that tries both.
        var world = new MotionWorld();
        BodyId ball = world.AddCircle(50f, Vector2.Zero);
        world.AddStatic(new Aabb(new Vector2(40f, -50f), new Vector2(90f, 50f)));
        Assert.Throws<ArgumentNullException>(() => world.Wedging = null!);
        var contact = world.Detect(ball, world.IdAt(1));
        Assert.True(contact.Intersect);

        // Between steps nothing is counted: a hundred deep corrections reject nothing.
        for (int i = 0; i < 100; i++)
        {
            Assert.False(world.CountCorrection(ball, contact));
        }

        Assert.False(world.WasRejected(ball));
        Assert.Equal(Vector2.Zero, world.PositionOf(ball));

        var during = new DuringStep();
        world.Settle(during);
        Assert.Equal("value", during.PolicyRefused?.ParamName);
        Assert.Equal("body", during.StaticRefused?.ParamName);
    }

    // Ball a (radius 50) starts a step at the origin and ends it there; then it is placed
    // `overlap` mm into ball b (radius 50, at 400, 0).
    private static (MotionWorld MotionWorld, BodyId A, BodyId B) JumpedInto(float overlap)
    {
        var world = new MotionWorld();
        BodyId a = world.AddCircle(50f, Vector2.Zero);
        BodyId b = world.AddCircle(50f, new Vector2(400f, 0f));
        world.Step(0.1f, new CountingHandler(default, 0));
        world.SetPose(a, new Vector2(300f + overlap, 0f), 0f);
        return (world, a, b);
    }

    // Counts `perContact` corrections of `body` for every contact it is in (records the verdicts),
    // then pushes the pair apart along the MTV (b takes it all when a's move was rejected).
    private sealed class CountingHandler(BodyId body, int perContact) : IContactHandler
    {
        public List<bool> Verdicts { get; } = [];

        public List<BodyId> Rejected { get; } = [];

        public int Contacts { get; private set; }

        public void OnContact(MotionWorld world, in Contact contact)
        {
            Contacts++;
            if (contact.BodyA == body || contact.BodyB == body)
            {
                for (int i = 0; i < perContact; i++)
                {
                    Verdicts.Add(world.CountCorrection(body, contact));
                }
            }

            Vector2 mtv = XZPlane.ToPlane(contact.Result.MinimumTranslationVector);
            Vector2 n = XZPlane.ToPlane(contact.Result.NormalAxis);
            Vector2 push = mtv + (n * 0.01f);
            if (!world.WasRejected(contact.BodyA))
            {
                world.SetPose(contact.BodyA, world.PositionOf(contact.BodyA) + push, 0f);
            }
            else if (world.KindOf(contact.BodyB) <= BodyKind.Fish)
            {
                world.SetPose(contact.BodyB, world.PositionOf(contact.BodyB) - push, 0f);
            }
        }

        public void OnMoveRejected(MotionWorld world, BodyId rejected) => Rejected.Add(rejected);
    }

    // Tries to change the policy and to count a static body's correction from a handler.
    private sealed class DuringStep : IContactHandler
    {
        public ArgumentException? PolicyRefused { get; private set; }

        public ArgumentException? StaticRefused { get; private set; }

        public void OnContact(MotionWorld world, in Contact contact)
        {
            PolicyRefused ??= Record(() => world.Wedging = new WedgePolicy());
            BodyId other = contact.BodyB;
            Contact copy = contact;
            if (world.KindOf(other) == BodyKind.Static)
            {
                StaticRefused ??= Record(() => world.CountCorrection(other, copy));
            }

            Vector2 push = XZPlane.ToPlane(contact.Result.MinimumTranslationVector) * 1.01f;
            world.SetPose(contact.BodyA, world.PositionOf(contact.BodyA) + push, 0f);
        }

        public void OnMoveRejected(MotionWorld world, BodyId rejected)
        {
        }

        private static ArgumentException? Record(Action action)
        {
            try
            {
                action();
                return null;
            }
            catch (ArgumentException e)
            {
                return e;
            }
        }
    }
}
