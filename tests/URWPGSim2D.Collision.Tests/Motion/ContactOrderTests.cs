namespace URWPGSim2D.Collision.Tests.Motion;

/// <summary>
/// Before the handler responds to a contact, the motion world involves the contact's moving bodies
/// in the order the separation moves them: A first, unless A's move was rejected, A is not a circle
/// and B's move was not rejected; then B first, since B alone is pushed away from A.
/// </summary>
public sealed class ContactOrderTests
{
    [Fact]
    public void TwoBallsAreInvolvedAThenB()
    {
        var world = new MotionWorld();
        BodyId a = world.AddCircle(20f, Vector2.Zero);
        BodyId b = world.AddCircle(20f, new Vector2(200f, 0f));
        world.SetVelocity(a, new Vector2(1000f, 0f));
        var handler = new OrderHandler(rejectFirst: false);
        world.Step(0.5f, handler);

        Assert.NotEmpty(handler.Orders);
        Assert.Equal([a, b], handler.Orders[0]);
    }

    [Fact]
    public void ABodyWhoseMoveWasRejectedHoldsStillUnlessItIsACircle()
    {
        // The first body runs into a resting ball; the response rejects its move (back to the step's
        // start, at rest). A second ball then runs into it from behind: a polygon holds still and the
        // ball is involved first; a circle is pushed like any ball and is involved first itself.
        var square = new ConvexPolygon([new Vector2(-20f, -20f), new Vector2(20f, -20f), new Vector2(20f, 20f), new Vector2(-20f, 20f)]);
        foreach (bool polygon in new[] { true, false })
        {
            var world = new MotionWorld();
            BodyId first = polygon ? world.AddPolygon(square, Vector2.Zero, 0f) : world.AddCircle(20f, Vector2.Zero);
            world.AddCircle(20f, new Vector2(200f, 0f));
            BodyId behind = world.AddCircle(20f, new Vector2(-300f, 0f));
            world.SetVelocity(first, new Vector2(1000f, 0f));
            world.SetVelocity(behind, new Vector2(1000f, 0f));
            var handler = new OrderHandler(rejectFirst: true);
            world.Step(0.5f, handler);

            Assert.True(world.WasRejected(first));
            int hit = handler.Pairs.FindIndex(p => p == (first, behind));
            Assert.True(hit >= 0, $"polygon {polygon}: the ball behind never met the first body");
            Assert.Equal(polygon ? [behind, first] : [first, behind], handler.Orders[hit]);
        }
    }

    // Records, at each contact, the order in which its two bodies were involved before the response;
    // rejects the move of the first contact's body A, and pushes a later contact's B out and stops it.
    private sealed class OrderHandler(bool rejectFirst) : IContactHandler
    {
        public List<BodyId[]> Orders { get; } = [];

        public List<(BodyId, BodyId)> Pairs { get; } = [];

        public void OnContact(MotionWorld world, in Contact contact)
        {
            BodyId a = contact.BodyA, b = contact.BodyB;
            Orders.Add([.. world.ChangedInOrder().Where(id => id == a || id == b)]);
            Pairs.Add((a, b));
            if (rejectFirst && Pairs.Count == 1)
            {
                world.RejectMove(a);
                return;
            }

            Vector2 mtv = XZPlane.ToPlane(contact.Result.MinimumTranslationVector);
            Vector2 n = XZPlane.ToPlane(contact.Result.NormalAxis);
            world.SetPose(b, world.PositionOf(b) - mtv - (n * 0.01f), world.HeadingOf(b));
            world.SetVelocity(b, Vector2.Zero);
            if (!world.WasRejected(a))
            {
                world.SetVelocity(a, Vector2.Zero);
            }
        }

        public void OnMoveRejected(MotionWorld world, BodyId body)
        {
        }
    }
}
