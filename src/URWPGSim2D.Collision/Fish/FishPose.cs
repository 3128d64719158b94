namespace URWPGSim2D.Collision.Fish;

/// <summary>
/// Where a fish is and how it is bent: the centre of its body rectangle, its heading, and the
/// three tail joint angles. Each joint angle is measured from the body axis (not added to the
/// previous joint): tail segment i points backward along the world direction
/// <see cref="Heading"/> + joint i.
/// </summary>
public readonly struct FishPose : IEquatable<FishPose>
{
    /// <summary>Creates and validates a pose.</summary>
    /// <param name="position">Centre of the body rectangle, mm (X = world X, Y = world Z).</param>
    /// <param name="heading">Heading θ in radians, from +X toward +Z (any finite value; not wrapped).</param>
    /// <param name="joint1">Angle φ1 of tail segment 1 from the body axis, rad.</param>
    /// <param name="joint2">Angle φ2 of tail segment 2 from the body axis, rad.</param>
    /// <param name="joint3">Angle φ3 of tail segment 3 from the body axis, rad.</param>
    /// <exception cref="ArgumentException">A value is not finite (the message names the parameter and the value).</exception>
    public FishPose(Vector2 position, float heading, float joint1 = 0f, float joint2 = 0f, float joint3 = 0f)
    {
        Guard.Finite(position, nameof(position));
        Guard.Finite(heading, nameof(heading));
        Guard.Finite(joint1, nameof(joint1));
        Guard.Finite(joint2, nameof(joint2));
        Guard.Finite(joint3, nameof(joint3));
        Position = position;
        Heading = heading;
        Joint1 = joint1;
        Joint2 = joint2;
        Joint3 = joint3;
    }

    /// <summary>Centre of the body rectangle, mm (X = world X, Y = world Z).</summary>
    public Vector2 Position { get; }

    /// <summary>Heading θ, rad, measured from +X toward +Z.</summary>
    public float Heading { get; }

    /// <summary>Joint angle φ1 of tail segment 1, rad, from the body axis.</summary>
    public float Joint1 { get; }

    /// <summary>Joint angle φ2 of tail segment 2, rad, from the body axis.</summary>
    public float Joint2 { get; }

    /// <summary>Joint angle φ3 of tail segment 3, rad, from the body axis.</summary>
    public float Joint3 { get; }

    /// <summary>The same pose moved by <paramref name="offset"/> mm (heading and joints kept).</summary>
    /// <param name="offset">Translation in mm.</param>
    /// <returns>The translated pose.</returns>
    public FishPose Translated(Vector2 offset) => new(Position + offset, Heading, Joint1, Joint2, Joint3);

    /// <inheritdoc />
    public bool Equals(FishPose other) =>
        Position == other.Position && Heading == other.Heading
        && Joint1 == other.Joint1 && Joint2 == other.Joint2 && Joint3 == other.Joint3;

    /// <inheritdoc />
    public override bool Equals(object? obj) => obj is FishPose other && Equals(other);

    /// <inheritdoc />
    public override int GetHashCode() => HashCode.Combine(Position, Heading, Joint1, Joint2, Joint3);

    /// <summary>Compares two poses value by value.</summary>
    public static bool operator ==(FishPose left, FishPose right) => left.Equals(right);

    /// <summary>Compares two poses value by value.</summary>
    public static bool operator !=(FishPose left, FishPose right) => !left.Equals(right);

    /// <inheritdoc />
    public override string ToString() => $"P=({Position.X}, {Position.Y}) θ={Heading} φ={Joint1}/{Joint2}/{Joint3}";
}
