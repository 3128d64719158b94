namespace URWPGSim2D.Collision.NarrowPhase;

/// <summary>
/// The first half of a contact: normal and depth, without the action point. A deepest-contact
/// query compares many of these and completes only the winner (the action point costs more
/// than the depth). For a separating-axis contact it also keeps the two shapes' best faces and
/// separations, which the completion needs.
/// </summary>
internal readonly struct ContactDepth
{
    /// <summary>A circle contact: unit normal (from b toward a) and depth.</summary>
    public ContactDepth(Vector2 normal, float depth)
        : this(normal, depth, -1, float.NegativeInfinity, -1, float.NegativeInfinity)
    {
    }

    /// <summary>A separating-axis contact: normal, depth, and each shape's face of greatest separation.</summary>
    public ContactDepth(Vector2 normal, float depth, int faceA, float separationA, int faceB, float separationB)
    {
        Normal = normal;
        Depth = depth;
        FaceA = faceA;
        SeparationA = separationA;
        FaceB = faceB;
        SeparationB = separationB;
    }

    /// <summary>Unit normal from b toward a (plane vector).</summary>
    public Vector2 Normal { get; }

    /// <summary>Penetration depth, mm.</summary>
    public float Depth { get; }

    /// <summary>Face of a with the greatest separation (−1: none).</summary>
    public int FaceA { get; }

    /// <summary>That face's separation (negative), mm.</summary>
    public float SeparationA { get; }

    /// <summary>Face of b with the greatest separation (−1: none).</summary>
    public int FaceB { get; }

    /// <summary>That face's separation (negative), mm.</summary>
    public float SeparationB { get; }

    /// <summary>
    /// |MTV|², computed exactly as the finished <see cref="CollisionDetectionResult"/> computes it
    /// (from its world-space MTV), so that comparing these picks the same contact as comparing results.
    /// </summary>
    public float MtvLengthSquared => XZPlane.ToWorld(Normal * Depth).LengthSquared();
}
