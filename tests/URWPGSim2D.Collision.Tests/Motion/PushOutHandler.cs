namespace URWPGSim2D.Collision.Tests.Motion;

/// <summary>
/// A response for tests: records every contact and every touch that begins or ends, moves body A
/// out along the MTV plus 0.01 mm and, unless told to keep it (<c>stop: false</c>), removes the
/// part of A's velocity into B. <see cref="Probe"/>, when set, runs first on every contact (a
/// test's check of what a handler may and may not do during a step).
/// </summary>
internal sealed class PushOutHandler(bool stop = true) : IContactHandler
{
    public List<Contact> Contacts { get; } = [];

    public List<(BodyId, BodyId)> Began { get; } = [];

    public List<(BodyId, BodyId)> Ended { get; } = [];

    public Action<MotionWorld>? Probe { get; init; }

    public void OnTouchBegan(MotionWorld world, BodyId bodyA, BodyId bodyB) => Began.Add((bodyA, bodyB));

    public void OnTouchEnded(MotionWorld world, BodyId bodyA, BodyId bodyB) => Ended.Add((bodyA, bodyB));

    public void OnContact(MotionWorld world, in Contact contact)
    {
        Probe?.Invoke(world);
        Contacts.Add(contact);
        BodyId a = contact.BodyA;
        world.SetPose(a, world.PositionOf(a) + contact.Mtv + (contact.Normal * 0.01f), world.HeadingOf(a));
        Vector2 v = world.VelocityOf(a);
        float vn = Vector2.Dot(v, contact.Normal);
        if (stop && vn < 0f)
        {
            world.SetVelocity(a, v - (vn * contact.Normal), world.AngularVelocityOf(a));
        }
    }

    public void OnMoveRejected(MotionWorld world, BodyId body)
    {
    }
}
