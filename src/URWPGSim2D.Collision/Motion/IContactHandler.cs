namespace URWPGSim2D.Collision.Motion;

/// <summary>
/// The response hook of a <see cref="MotionWorld"/>: the caller's contact response. The motion world stops
/// every body of a contact at its time of first contact and calls <see cref="OnContact"/>; the
/// handler may change the poses (<see cref="MotionWorld.SetPose"/>, <see cref="MotionWorld.SetJoints"/>)
/// and velocities (<see cref="MotionWorld.SetVelocity"/>) of the bodies it is given, test pairs
/// again (<see cref="MotionWorld.Detect"/>) while it separates them, and the motion world carries on from
/// there with the new state, planning again only the bodies that changed.
/// </summary>
public interface IContactHandler
{
    /// <summary>Responds to one contact: both bodies are at <see cref="Contact.Time"/> and overlap as <paramref name="contact"/> says.</summary>
    /// <param name="world">The motion world (to read and change the bodies' state).</param>
    /// <param name="contact">The contact at its time of first contact.</param>
    void OnContact(MotionWorld world, in Contact contact);

    /// <summary>
    /// Reports that the motion world rejected a body's move at the end of a step: its response left it
    /// inside another body, so it went back to its pose (and joints) at the end of the previous
    /// step and its velocity became zero. Called after the step's last contact.
    /// </summary>
    /// <param name="world">The motion world.</param>
    /// <param name="body">The body whose move was rejected.</param>
    void OnMoveRejected(MotionWorld world, BodyId body);
}
