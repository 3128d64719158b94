namespace URWPGSim2D.Collision.Fish;

/// <summary>
/// A contact found by a fish query: the leaf-level <see cref="CollisionDetectionResult"/>
/// (same conventions: the MTV moves the first argument, the normal points from the second
/// toward the first) and which part of each fish it involves.
/// </summary>
public readonly struct FishContact : IEquatable<FishContact>
{
    // Leaf index + 1, 0 for "not a fish": keeps the struct small in callers' spans.
    private readonly byte _partA;
    private readonly byte _partB;

    /// <summary>Creates a contact from a result and the parts involved.</summary>
    /// <param name="result">The leaf contact; the MTV moves the first argument.</param>
    /// <param name="partA">The part of the first argument, or null when it is not a fish.</param>
    /// <param name="partB">The part of the second argument, or null when it is not a fish.</param>
    /// <exception cref="ArgumentException">A part is not one of the eight <see cref="FishPart"/> values.</exception>
    public FishContact(CollisionDetectionResult result, FishPart? partA, FishPart? partB)
    {
        Result = result;
        _partA = Encode(partA, nameof(partA));
        _partB = Encode(partB, nameof(partB));
    }

    private FishContact(CollisionDetectionResult result, byte partA, byte partB)
    {
        Result = result;
        _partA = partA;
        _partB = partB;
    }

    /// <summary>No contact: <see cref="CollisionDetectionResult.None"/> and no parts.</summary>
    public static FishContact None => default;

    /// <summary>The leaf contact (MTV moves the first argument of the query).</summary>
    public CollisionDetectionResult Result { get; }

    /// <summary>The part of the first argument's fish, or null when the first argument is not a fish (or there is no contact).</summary>
    public FishPart? PartA => _partA == 0 ? null : (FishPart)(_partA - 1);

    /// <summary>The part of the second argument's fish, or null when the second argument is not a fish (or there is no contact).</summary>
    public FishPart? PartB => _partB == 0 ? null : (FishPart)(_partB - 1);

    /// <summary>Whether the two arguments overlap.</summary>
    public bool Intersect => Result.Intersect;

    /// <summary>The same contact seen with the arguments swapped: result swapped, parts exchanged.</summary>
    /// <returns>The swapped contact.</returns>
    public FishContact Swapped() => new(Result.Swapped(), _partB, _partA);

    /// <summary>A contact of leaf <paramref name="leafA"/> of the first argument with a non-fish second argument.</summary>
    internal static FishContact OfLeafA(CollisionDetectionResult result, int leafA) => new(result, (byte)(leafA + 1), 0);

    /// <summary>A contact of leaf <paramref name="leafA"/> of fish a with leaf <paramref name="leafB"/> of fish b.</summary>
    internal static FishContact OfLeaves(CollisionDetectionResult result, int leafA, int leafB) =>
        new(result, (byte)(leafA + 1), (byte)(leafB + 1));

    /// <inheritdoc />
    public bool Equals(FishContact other) => Result == other.Result && _partA == other._partA && _partB == other._partB;

    /// <inheritdoc />
    public override bool Equals(object? obj) => obj is FishContact other && Equals(other);

    /// <inheritdoc />
    public override int GetHashCode() => HashCode.Combine(Result, _partA, _partB);

    /// <summary>Compares result and parts.</summary>
    public static bool operator ==(FishContact left, FishContact right) => left.Equals(right);

    /// <summary>Compares result and parts.</summary>
    public static bool operator !=(FishContact left, FishContact right) => !left.Equals(right);

    /// <inheritdoc />
    public override string ToString() => $"{Result} parts {PartA?.ToString() ?? "-"} / {PartB?.ToString() ?? "-"}";

    private static byte Encode(FishPart? part, string paramName) =>
        part is { } p ? (byte)(FishLeafLayout.Index(p, paramName) + 1) : (byte)0;
}
