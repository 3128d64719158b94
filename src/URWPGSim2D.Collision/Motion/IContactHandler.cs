namespace URWPGSim2D.Collision.Motion;

/// <summary>
/// The response hook of a <see cref="MotionWorld"/>: the caller's contact response. The motion world stops
/// every body of a contact at its time of first contact and calls <see cref="OnContact"/>; the
/// handler may change the poses (<see cref="MotionWorld.SetPose"/>, <see cref="MotionWorld.SetJoints"/>)
/// and velocities (<see cref="MotionWorld.SetVelocity"/>) of the bodies it is given, test pairs
/// again (<see cref="MotionWorld.Detect"/>) while it separates them, and the motion world carries on from
/// there with the new state, planning again only the bodies that changed. A response in two parts
/// moves the bodies out of the contact in <see cref="OnSeparate"/> first: the motion world counts
/// those corrections against its wedge policy (<see cref="MotionWorld.Wedging"/>) before it calls
/// <see cref="OnContact"/>, where <see cref="MotionWorld.WasRejected"/> tells whether one of them
/// was the correction too many.
/// </summary>
public interface IContactHandler
{
    /// <summary>
    /// The position correction of one contact, called just before <see cref="OnContact"/> with the
    /// same contact (nothing by default). Each moving body this call moves or turns counts a
    /// correction for the contact, a fish's or a polygon's (a circle, pushed by whatever presses it,
    /// never counts, nor does a pressing contact, <see cref="Contact.Pressing"/>): past <see cref="WedgePolicy.CorrectionsBeforeRejecting"/> deep ones (of a
    /// contact deeper than <see cref="MotionTolerances.TimeOfImpactTolerance"/>) in a step, a
    /// <see cref="MotionWorld.Settle"/> after it included, the body is wedged and the motion world
    /// rejects its move at once, as by <see cref="MotionWorld.RejectMove"/>, before <see cref="OnContact"/>.
    /// </summary>
    /// <param name="world">The motion world (to read and change the bodies' state).</param>
    /// <param name="contact">The contact at its time of first contact.</param>
    void OnSeparate(MotionWorld world, in Contact contact)
    {
    }

    /// <summary>Responds to one contact: both bodies are at <see cref="Contact.Time"/> and overlap as <paramref name="contact"/> says.</summary>
    /// <param name="world">The motion world (to read and change the bodies' state).</param>
    /// <param name="contact">The contact at its time of first contact.</param>
    void OnContact(MotionWorld world, in Contact contact);

    /// <summary>
    /// Reports that two bodies begin to touch: the motion world is about to ask for the first answer
    /// to a contact of theirs (called just before <see cref="OnSeparate"/>), and they were not
    /// touching (no answer in this step or the one before). Nothing by default.
    /// </summary>
    /// <param name="world">The motion world.</param>
    /// <param name="bodyA">The contact's first body (a moving one).</param>
    /// <param name="bodyB">The contact's second body.</param>
    void OnTouchBegan(MotionWorld world, BodyId bodyA, BodyId bodyB)
    {
    }

    /// <summary>
    /// Reports that two bodies no longer touch: a whole step passed without an answer to a contact
    /// of theirs. Called at the end of that step, after its last contact and its rejected moves,
    /// with the bodies in the order <see cref="OnTouchBegan"/> gave them. Nothing by default.
    /// </summary>
    /// <param name="world">The motion world.</param>
    /// <param name="bodyA">The first body of the contact that began the touch.</param>
    /// <param name="bodyB">Its second body.</param>
    void OnTouchEnded(MotionWorld world, BodyId bodyA, BodyId bodyB)
    {
    }

    /// <summary>
    /// Reports that the motion world rejected a body's move at the end of a step: its response left it
    /// inside another body, so it went back to its pose (and joints) at the end of the previous
    /// step and its velocity became zero. Called after the step's last contact.
    /// </summary>
    /// <param name="world">The motion world.</param>
    /// <param name="body">The body whose move was rejected.</param>
    void OnMoveRejected(MotionWorld world, BodyId body);
}
