using URWPGSim2D.Collision.Benchmarks.Baseline.Motion;
using URWPGSim2D.Server.Simulation;

namespace URWPGSim2D.Collision.Benchmarks.Baseline.Cycle;

/// <summary>
/// The server's response hook for the library's stepper: the contact's two bodies are brought into
/// the world at the time of first contact, <see cref="ContactResponse"/> applies the reference's
/// position correction and impulses, the contact is logged for the trace and the summary, and the
/// bodies' new poses and velocities go back to the stepper. A rejected move (the body went back to
/// where it ended the last cycle) stops the body for the rest of the cycle.
/// </summary>
internal sealed class ContactHandler(World world, ContactLog log, MotionBodies bodies) : IContactHandler
{
    private readonly ContactResponse _response = new(world, bodies);

    /// <inheritdoc/>
    public void OnContact(Stepper stepper, in Contact contact)
    {
        bodies.Pull(contact.BodyA);
        bodies.Pull(contact.BodyB);
        CandidatePair pair = bodies.PairOf(contact);
        Hit hit = MotionBodies.ToHit(contact);
        ContactKind kind = _response.Apply(pair, hit);
        log.Add(new ContactRecord(pair, hit.PartA, hit.PartB, hit.Mtv, hit.Normal, hit.Point, contact.Time), kind);
        bodies.Push(contact.BodyA);
        bodies.Push(contact.BodyB);
    }

    /// <inheritdoc/>
    public void OnMoveRejected(Stepper stepper, int body)
    {
        bodies.Pull(body);
        if (bodies.IsFish(body))
        {
            bodies.PullJoints(body);
            var f = world.Fish[body];
            f.Velocity = default;
            f.AngularVelocity = 0f;
            f.NoiseVelocity = default;
            f.NoiseAngularVelocity = 0f;
            f.Frozen = true;
        }
        else
        {
            var b = world.Balls[body - world.Fish.Length];
            b.Velocity = default;
            b.NoiseVelocity = default;
        }
    }
}
