namespace URWPGSim2D.Collision.Fish;

/// <summary>
/// The dimensions of a multi-joint fish, mm: body rectangle length × width, head length in
/// front of it, and the lengths of the three tail segments. Every value must be finite and
/// &gt; 0, and the sizes must give eight non-degenerate leaf polygons.
/// </summary>
public readonly struct FishSize : IEquatable<FishSize>
{
    /// <summary>Creates and validates a fish size (all mm).</summary>
    /// <param name="length">Body rectangle length L along the fish axis.</param>
    /// <param name="width">Body rectangle width W across the fish axis.</param>
    /// <param name="head">Head length H: the head tip is H in front of the body rectangle.</param>
    /// <param name="joint1">Length L1 of tail segment 1.</param>
    /// <param name="joint2">Length L2 of tail segment 2.</param>
    /// <param name="joint3">Length L3 of tail segment 3 (the caudal fin reaches 2·L3 behind segment 3's start).</param>
    /// <exception cref="ArgumentException">A value is not finite or not &gt; 0, or a leaf polygon would have collinear vertices (the message names the parameter and the value).</exception>
    public FishSize(float length, float width, float head, float joint1, float joint2, float joint3)
    {
        Guard.Positive(length, nameof(length));
        Guard.Positive(width, nameof(width));
        Guard.Positive(head, nameof(head));
        Guard.Positive(joint1, nameof(joint1));
        Guard.Positive(joint2, nameof(joint2));
        Guard.Positive(joint3, nameof(joint3));
        Length = length;
        Width = width;
        Head = head;
        Joint1 = joint1;
        Joint2 = joint2;
        Joint3 = joint3;

        // Only the left caudal lobe mixes fixed offsets (mm) with size ratios; it turns flat
        // (and flips its winding) at one value of joint3 (about 1667 mm).
        FishPart? flat = FishLocalGeometry.FindDegenerateLeaf(this);
        if (flat is not null)
        {
            throw new ArgumentException($"joint3 = {joint3} makes the {flat} leaf polygon degenerate (its vertices are collinear)", nameof(joint3));
        }
    }

    /// <summary>The deployed configuration of the original simulator: 160 × 45, head 30, joints 88 / 66 / 55 mm.</summary>
    public static FishSize Default { get; } = new(160f, 45f, 30f, 88f, 66f, 55f);

    /// <summary>Body rectangle length L, mm.</summary>
    public float Length { get; }

    /// <summary>Body rectangle width W, mm.</summary>
    public float Width { get; }

    /// <summary>Head length H in front of the body rectangle, mm.</summary>
    public float Head { get; }

    /// <summary>Tail segment 1 length L1, mm.</summary>
    public float Joint1 { get; }

    /// <summary>Tail segment 2 length L2, mm.</summary>
    public float Joint2 { get; }

    /// <summary>Tail segment 3 length L3, mm.</summary>
    public float Joint3 { get; }

    /// <summary>True for a validated size (false for <c>default(FishSize)</c>, whose values are all 0).</summary>
    internal bool IsValid => Length > 0f;

    /// <inheritdoc />
    public bool Equals(FishSize other) =>
        Length == other.Length && Width == other.Width && Head == other.Head
        && Joint1 == other.Joint1 && Joint2 == other.Joint2 && Joint3 == other.Joint3;

    /// <inheritdoc />
    public override bool Equals(object? obj) => obj is FishSize other && Equals(other);

    /// <inheritdoc />
    public override int GetHashCode() => HashCode.Combine(Length, Width, Head, Joint1, Joint2, Joint3);

    /// <summary>Compares two sizes value by value.</summary>
    public static bool operator ==(FishSize left, FishSize right) => left.Equals(right);

    /// <summary>Compares two sizes value by value.</summary>
    public static bool operator !=(FishSize left, FishSize right) => !left.Equals(right);

    /// <inheritdoc />
    public override string ToString() => $"L={Length} W={Width} H={Head} joints={Joint1}/{Joint2}/{Joint3}";
}
