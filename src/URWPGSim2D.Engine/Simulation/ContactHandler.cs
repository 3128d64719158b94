using URWPGSim2D.Collision.Fish;
using URWPGSim2D.Collision.Motion;

namespace URWPGSim2D.Engine.Simulation;

/// <summary>
/// The server's response hook for the motion world: at the time of first contact (or, for a pair
/// already touching, at a sub-step's end) <see cref="ContactResponse"/> applies the reference's position correction (its fish corrections
/// counted by the motion world's wedge policy) and then the impulses to the two bodies where they are (their poses and velocities are the motion world's, changed in
/// place), and the contact is logged for the trace and the summary. A rejected move (the body went
/// back to where it ended the last cycle) stops the body for the rest of the cycle.
/// </summary>
internal sealed class ContactHandler(World world, ContactLog log) : IContactHandler
{
    private readonly ContactResponse _response = new(world);

    /// <summary>Forgets the contacts the response remembers (a match restarted in place).</summary>
    public void Restart() => _response.Restart();

    /// <inheritdoc/>
    public void OnSeparate(MotionWorld motionWorld, in Contact contact) => _response.Separate(world.PairOf(contact), contact);

    /// <inheritdoc/>
    public void OnContact(MotionWorld motionWorld, in Contact contact)
    {
        CandidatePair pair = world.PairOf(contact);
        ContactKind kind = _response.Respond(pair, contact);
        log.Add(new ContactRecord(pair, Part(contact.PartA), Part(contact.PartB), contact.Mtv, contact.Normal, contact.Point, contact.Time), kind);
    }

    /// <inheritdoc/>
    public void OnMoveRejected(MotionWorld motionWorld, BodyId body)
    {
        // The motion world put the body back and stopped it (velocity and noise drift zero) and
        // remembers it (FishState.MoveRejected): a fish holds still, immovable in contacts, for
        // the rest of the cycle. Nothing to keep here.
    }

    // A leaf index for the contact record, −1 for "not a fish".
    private static sbyte Part(FishPart? part) => part.HasValue ? (sbyte)part.Value : (sbyte)-1;
}
