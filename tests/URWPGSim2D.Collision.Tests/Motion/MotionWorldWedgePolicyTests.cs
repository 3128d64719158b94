namespace URWPGSim2D.Collision.Tests.Motion;

/// <summary>
/// The motion world's one wedge policy (<see cref="MotionWorld.Wedging"/>): the corrections a handler
/// makes in <see cref="IContactHandler.OnSeparate"/> are counted by the motion world itself, per body
/// and step, against the policy's allowance; the first deep one past it rejects the move before
/// <see cref="IContactHandler.OnContact"/>, which reads the verdict with <see cref="MotionWorld.WasRejected"/>.
/// The events before a body's contacts are left to the end of the step are the policy's too.
/// </summary>
public sealed class MotionWorldWedgePolicyTests
{
    [Fact]
    public void TheFirstDeepCorrectionPastTheAllowanceRejectsTheMoveOnce()
    {
        // Square a is thrown 50 mm into ball b between steps; settling reports their contact pass
        // after pass, and each separation pushes a out by 1 mm only (still deep).
        var (world, a, _) = JumpedInto(BodyKind.Polygon, overlap: 50f);
        var handler = new PushingHandler(a, push: 1f);
        world.Settle(handler);

        // Default allowance 8: the ninth correction rejects; back at the step's start, a meets nothing more.
        Assert.Equal(8, new WedgePolicy().CorrectionsBeforeRejecting);
        Assert.Equal([false, false, false, false, false, false, false, false, true], handler.Verdicts);
        Assert.Equal([a], handler.Rejected);
        Assert.True(world.WasRejected(a));

        // Rejected as RejectMove rejects: back where the last step began (its start, 0,0), at rest.
        Assert.Equal(Vector2.Zero, world.PositionOf(a));
        Assert.Equal(Vector2.Zero, world.VelocityOf(a));
    }

    [Theory]
    [InlineData(BodyKind.Circle, true)]
    [InlineData(BodyKind.Polygon, false)]
    public void OnlyAFishOrPolygonMovedInTheSeparationCounts(BodyKind kind, bool inSeparation)
    {
        // A circle pushed in the separation, or a polygon pushed in OnContact (a handler that does
        // not separate first), is never rejected for its corrections: only the end of the settle,
        // which finds it (and b) still 30-odd mm inside each other, rejects its move.
        var (world, a, _) = JumpedInto(kind, overlap: 50f);
        var handler = new PushingHandler(a, push: 1f) { InSeparation = inSeparation };
        world.Settle(handler);

        Assert.True(handler.Verdicts.Count > 9, $"{handler.Verdicts.Count} contacts");
        Assert.All(handler.Verdicts, v => Assert.False(v));
        Assert.Contains(a, handler.Rejected);
    }

    [Fact]
    public void ShallowCorrectionsAreNotCounted()
    {
        // 0.2 mm deep: within the time-of-impact tolerance (0.25 mm), a correction at a refined time of first contact.
        var (world, a, _) = JumpedInto(BodyKind.Polygon, overlap: 0.2f);
        var handler = new PushingHandler(a, push: 0.001f);
        world.Settle(handler);

        Assert.True(handler.Verdicts.Count > 9, $"{handler.Verdicts.Count} contacts");
        Assert.All(handler.Verdicts, v => Assert.False(v));
        Assert.Empty(handler.Rejected);
        Assert.False(world.WasRejected(a));
    }

    [Fact]
    public void TheAllowanceIsThePolicys()
    {
        var (world, a, _) = JumpedInto(BodyKind.Polygon, overlap: 50f);
        world.Wedging = new WedgePolicy { CorrectionsBeforeRejecting = 2 };
        var handler = new PushingHandler(a, push: 1f);
        world.Settle(handler);
        Assert.Equal([false, false, true], handler.Verdicts);

        var (strict, b, _) = JumpedInto(BodyKind.Polygon, overlap: 50f);
        strict.Wedging = new WedgePolicy { CorrectionsBeforeRejecting = 0 };
        var first = new PushingHandler(b, push: 1f);
        strict.Settle(first);
        Assert.Equal([true], first.Verdicts);
    }

    [Fact]
    public void TheCountRunsThroughSettlesAndStartsAgainWithAStep()
    {
        // Six corrections in one settle (five 1 mm pushes, then one that frees a), six in the next:
        // the ninth of the step rejects.
        var (world, a, b) = JumpedInto(BodyKind.Polygon, overlap: 50f);
        var handler = new PushingHandler(a, push: 1f) { FreeAfter = 6 };
        world.Settle(handler);
        Assert.Equal(6, handler.Verdicts.Count);
        world.SetPose(a, world.PositionOf(b) - new Vector2(50f, 0f), 0f);
        handler.FreeAfter = 12;
        world.Settle(handler);
        Assert.Equal([false, false, false, false, false, false, false, false, true], handler.Verdicts);

        // A step between the two settles starts the count again: twelve corrections, none rejects.
        var (other, c, d) = JumpedInto(BodyKind.Polygon, overlap: 50f);
        var again = new PushingHandler(c, push: 1f) { FreeAfter = 6 };
        other.Settle(again);
        other.Step(0.1f, again);
        other.SetPose(c, other.PositionOf(d) - new Vector2(50f, 0f), 0f);
        again.FreeAfter = 12;
        other.Settle(again);
        Assert.Equal(12, again.Verdicts.Count);
        Assert.All(again.Verdicts, v => Assert.False(v));
        Assert.False(other.WasRejected(c));
    }

    [Fact]
    public void TheEventsThatMakeABarWedgedAreThePolicys()
    {
        int Most(WedgePolicy? policy, bool pressing = false)
        {
            var world = MotionWorldWedgeTests.BarInSlot(out BodyId body);
            world.PressingContacts = pressing;
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

        // Every contact answered at its time of first contact (the default): the bar is found wedged
        // by its events in a row at one time (2 by default); with that rule off (a large count) it
        // takes many events a step, and the events-per-step rule bounds them.
        int usual = Most(null);
        int many = Most(new WedgePolicy { EventsInPlaceBeforeDeferring = 1000 });
        int strict = Most(new WedgePolicy { EventsInPlaceBeforeDeferring = 1000, EventsBeforeDeferring = 4 });
        Assert.True(many > usual, $"in place off {many} events, default {usual}");
        Assert.True(many <= 16 + 2, $"in place off {many} events in one step");
        Assert.True(strict <= 4 + 2, $"{strict} events in one step");
        Assert.True(strict < many, $"16 events before deferring: {many}, 4: {strict}");

        // With pressing contacts on, the bar's contacts after the first are answered where they are
        // found: no more events than the policy allows at times of first contact, even with its rules off.
        int pressing = Most(null, pressing: true);
        int pressingUnbounded = Most(new WedgePolicy { EventsInPlaceBeforeDeferring = 1000 }, pressing: true);
        Assert.True(pressing <= usual, $"pressing {pressing} events, at times of first contact {usual}");
        Assert.True(pressingUnbounded <= usual, $"pressing with the in-place rule off {pressingUnbounded} events, at times of first contact {usual}");
    }

    [Fact]
    public void BadPoliciesAreRefusedByNameAndThePolicyHoldsThroughAStep()
    {
        var events = Assert.Throws<ArgumentException>(() => new WedgePolicy { EventsBeforeDeferring = 0 });
        Assert.Equal("eventsBeforeDeferring", events.ParamName);
        Assert.Contains("got 0", events.Message, StringComparison.Ordinal);
        Assert.Equal("eventsInPlaceBeforeDeferring", Assert.Throws<ArgumentException>(() => new WedgePolicy { EventsInPlaceBeforeDeferring = -1 }).ParamName);
        var corrections = Assert.Throws<ArgumentException>(() => new WedgePolicy { CorrectionsBeforeRejecting = -3 });
        Assert.Equal("correctionsBeforeRejecting", corrections.ParamName);
        Assert.Contains("got -3", corrections.Message, StringComparison.Ordinal);

        // A ball 10 mm into a static box: settling reports their contact to a handler that tries to change the policy.
        var world = new MotionWorld();
        world.AddCircle(50f, Vector2.Zero);
        world.AddStatic(new Aabb(new Vector2(40f, -50f), new Vector2(90f, 50f)));
        Assert.Throws<ArgumentNullException>(() => world.Wedging = null!);
        var during = new DuringStep();
        world.Settle(during);
        Assert.Equal("value", during.PolicyRefused?.ParamName);
    }

    // Body a (a ball of radius 50, or a 100 mm square) starts a step at the origin and ends it
    // there; then it is placed `overlap` mm into ball b (radius 50, at 400, 0).
    private static (MotionWorld MotionWorld, BodyId A, BodyId B) JumpedInto(BodyKind kind, float overlap)
    {
        var world = new MotionWorld();
        BodyId a = kind == BodyKind.Circle
            ? world.AddCircle(50f, Vector2.Zero)
            : world.AddPolygon(new ConvexPolygon([new Vector2(-50f, -50f), new Vector2(50f, -50f), new Vector2(50f, 50f), new Vector2(-50f, 50f)]), Vector2.Zero, 0f);
        BodyId b = world.AddCircle(50f, new Vector2(400f, 0f));
        world.Step(0.1f, new PushingHandler(default, 0f));
        world.SetPose(a, new Vector2(300f + overlap, 0f), 0f);
        return (world, a, b);
    }

    // Pushes `body` out of every contact it is in by `push` mm along the contact's normal (in the
    // separation, or in OnContact when InSeparation is false), or out of it entirely at the
    // FreeAfter-th contact; records in OnContact whether its move was rejected by then.
    private sealed class PushingHandler(BodyId body, float push) : IContactHandler
    {
        public List<bool> Verdicts { get; } = [];

        public List<BodyId> Rejected { get; } = [];

        public bool InSeparation { get; init; } = true;

        public int FreeAfter { get; set; } = int.MaxValue;

        public void OnSeparate(MotionWorld world, in Contact contact)
        {
            if (InSeparation)
            {
                Push(world, contact);
            }
        }

        public void OnContact(MotionWorld world, in Contact contact)
        {
            if (!InSeparation)
            {
                Push(world, contact);
            }

            if (contact.BodyA == body || contact.BodyB == body)
            {
                Verdicts.Add(world.WasRejected(body));
            }
        }

        public void OnMoveRejected(MotionWorld world, BodyId rejected) => Rejected.Add(rejected);

        private void Push(MotionWorld world, in Contact contact)
        {
            if ((contact.BodyA != body && contact.BodyB != body) || world.WasRejected(body))
            {
                return;
            }

            // The normal points from B toward A: a (as A) moves along it, (as B) against it.
            Vector2 n = XZPlane.ToPlane(contact.Result.NormalAxis) * (contact.BodyA == body ? 1f : -1f);
            float distance = Verdicts.Count + 1 >= FreeAfter ? contact.Depth + 0.01f : push;
            world.SetPose(body, world.PositionOf(body) + (n * distance), world.HeadingOf(body));
        }
    }

    // Tries to change the policy from a handler, then frees the pair.
    private sealed class DuringStep : IContactHandler
    {
        public ArgumentException? PolicyRefused { get; private set; }

        public void OnContact(MotionWorld world, in Contact contact)
        {
            try
            {
                world.Wedging = new WedgePolicy();
            }
            catch (ArgumentException e)
            {
                PolicyRefused ??= e;
            }

            Vector2 push = XZPlane.ToPlane(contact.Result.MinimumTranslationVector) * 1.01f;
            world.SetPose(contact.BodyA, world.PositionOf(contact.BodyA) + push, 0f);
        }

        public void OnMoveRejected(MotionWorld world, BodyId rejected)
        {
        }
    }
}
