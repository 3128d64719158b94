namespace URWPGSim2D.Collision.Tests.Motion;

/// <summary>
/// A simple response for tests: records every contact, pushes the moving body (or both, half each)
/// out along the MTV plus 0.01 mm (or, with <c>leaveOverlap</c> &gt; 0, out along the MTV but that
/// much short of apart), and removes the approaching part of the relative velocity along the normal
/// (optionally bouncing back with restitution e).
/// </summary>
internal sealed class RecordingHandler(float restitution = 0f, float leaveOverlap = 0f) : IContactHandler
{
    public List<Contact> Contacts { get; } = new(1024);

    public List<BodyId> Rejected { get; } = new(16);

    public bool Record { get; set; } = true;

    public void OnContact(MotionWorld world, in Contact contact)
    {
        if (Record)
        {
            Contacts.Add(contact);
        }

        BodyId a = contact.BodyA, b = contact.BodyB;
        bool bMoves = world.KindOf(b) <= BodyKind.Fish;
        Vector2 mtv = XZPlane.ToPlane(contact.Result.MinimumTranslationVector);
        Vector2 n = XZPlane.ToPlane(contact.Result.NormalAxis);
        float depth = mtv.Length();
        Vector2 push = leaveOverlap <= 0f ? mtv + (n * 0.01f) : depth > leaveOverlap ? mtv * ((depth - leaveOverlap) / depth) : Vector2.Zero;
        float share = bMoves ? 0.5f : 1f;
        world.SetPose(a, world.PositionOf(a) + (push * share), world.HeadingOf(a));
        if (bMoves)
        {
            world.SetPose(b, world.PositionOf(b) - (push * share), world.HeadingOf(b));
        }

        Vector2 va = world.VelocityOf(a), vb = bMoves ? world.VelocityOf(b) : Vector2.Zero;
        float vn = Vector2.Dot(va - vb, n);
        if (vn < 0f)
        {
            Vector2 dv = -(1f + restitution) * vn * n;
            world.SetVelocity(a, va + (dv * share), world.AngularVelocityOf(a));
            if (bMoves)
            {
                world.SetVelocity(b, vb - (dv * share), world.AngularVelocityOf(b));
            }
        }
    }

    public void OnMoveRejected(MotionWorld world, BodyId body)
    {
        if (Record)
        {
            Rejected.Add(body);
        }
    }
}
