using URWPGSim2D.Collision.Fish;
using URWPGSim2D.Collision.Motion;

namespace URWPGSim2D.Server.Simulation;

/// <summary>
/// The server's response hook for the library's stepper: the contact's two bodies are brought into
/// the world at the time of first contact, <see cref="ContactResponse"/> applies the reference's
/// position correction and impulses, the contact is logged for the trace and the summary, and the
/// bodies' new poses and velocities go back to the stepper. A rejected move (the body went back to
/// where it ended the last cycle) stops the body for the rest of the cycle.
/// </summary>
internal sealed class ContactHandler(World world, ContactLog log) : IContactHandler
{
    private readonly ContactResponse _response = new(world);

    /// <inheritdoc/>
    public void OnContact(Stepper stepper, in Contact contact)
    {
        MotionBodies bodies = world.Bodies;
        bodies.Pull(contact.BodyA);
        bodies.Pull(contact.BodyB);
        CandidatePair pair = bodies.PairOf(contact);
        ContactKind kind = _response.Apply(pair, contact);
        log.Add(new ContactRecord(pair, Part(contact.PartA), Part(contact.PartB), contact.Mtv, contact.Normal, contact.Point, contact.Time), kind);
        bodies.Push(contact.BodyA);
        bodies.Push(contact.BodyB);
    }

    /// <inheritdoc/>
    public void OnMoveRejected(Stepper stepper, int body)
    {
        MotionBodies bodies = world.Bodies;
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

    // A leaf index for the contact record, −1 for "not a fish".
    private static sbyte Part(FishPart? part) => part.HasValue ? (sbyte)part.Value : (sbyte)-1;
}
