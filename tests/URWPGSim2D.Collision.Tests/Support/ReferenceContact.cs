namespace URWPGSim2D.Collision.Tests.Support;

/// <summary>
/// The double-precision answer of <see cref="ReferenceGeometry.Contact"/>.
/// </summary>
/// <param name="SignedDepth">Penetration depth in mm when positive; minus the gap between the shapes when negative.</param>
/// <param name="Normal">Unit vector from b toward a along which the contact is resolved.</param>
public readonly record struct ReferenceContact(double SignedDepth, Point2 Normal)
{
    /// <summary>True when the interiors overlap (touching is not overlapping).</summary>
    public bool Intersect => SignedDepth > 0;

    /// <summary>The translation of a that leaves a and b just touching (pushes apart when overlapping, brings together when apart).</summary>
    public Point2 Mtv => Normal * SignedDepth;
}
