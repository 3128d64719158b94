namespace URWPGSim2D.Collision.Motion;

/// <summary>
/// The response hook of a <see cref="Stepper"/>: the caller's contact response. The stepper stops
/// every body of a contact at its time of first contact and calls <see cref="OnContact"/>; the
/// handler may change the poses (<see cref="Stepper.SetPose"/>, <see cref="Stepper.SetJoints"/>)
/// and velocities (<see cref="Stepper.SetVelocity"/>) of the bodies it is given, test pairs
/// again (<see cref="Stepper.Detect"/>) while it separates them, and the stepper carries on from
/// there with the new state, planning again only the bodies that changed.
/// </summary>
public interface IContactHandler
{
    /// <summary>Responds to one contact: both bodies are at <see cref="Contact.Time"/> and overlap as <paramref name="contact"/> says.</summary>
    /// <param name="stepper">The stepper (to read and change the bodies' state).</param>
    /// <param name="contact">The contact at its time of first contact.</param>
    void OnContact(Stepper stepper, in Contact contact);

    /// <summary>
    /// Reports that the stepper rejected a body's move at the end of a step: its response left it
    /// inside another body, so it went back to its pose (and joints) at the end of the previous
    /// step and its velocity became zero. Called after the step's last contact.
    /// </summary>
    /// <param name="stepper">The stepper.</param>
    /// <param name="body">The body whose move was rejected.</param>
    void OnMoveRejected(Stepper stepper, BodyId body);
}
