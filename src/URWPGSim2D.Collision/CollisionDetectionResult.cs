namespace URWPGSim2D.Collision;

/// <summary>
/// The answer of every collision test: whether two shapes overlap and, if they do, how to
/// separate them. All vectors lie in the world X–Z plane (Y is always 0), in millimetres.
/// </summary>
/// <remarks>
/// Conventions, shared with the original URWPGSim2D:
/// <list type="bullet">
/// <item><see cref="MinimumTranslationVector"/> is the shortest translation that, added to the
/// first shape <c>a</c>, leaves <c>a</c> and <c>b</c> just touching.</item>
/// <item><see cref="NormalAxis"/> is that vector divided by its length: a unit vector pointing
/// from <c>b</c> toward <c>a</c>.</item>
/// <item><see cref="ActionPoint"/> is a point of the contact region (inside both shapes or on
/// their boundaries).</item>
/// <item>When the shapes do not overlap (touching counts as not overlapping),
/// <see cref="Intersect"/> is false and every vector is zero.</item>
/// </list>
/// Swapping <c>a</c> and <c>b</c> negates the translation and the normal and keeps the action point.
/// </remarks>
public readonly struct CollisionDetectionResult : IEquatable<CollisionDetectionResult>
{
    /// <summary>Creates a result from its four parts (world X–Z vectors; Y is forced to 0).</summary>
    /// <param name="intersect">Whether the shapes overlap.</param>
    /// <param name="minimumTranslationVector">Shortest separating translation of the first shape, mm.</param>
    /// <param name="normalAxis">Unit normal from the second shape toward the first.</param>
    /// <param name="actionPoint">A point of the contact region, mm.</param>
    public CollisionDetectionResult(bool intersect, Vector3 minimumTranslationVector, Vector3 normalAxis, Vector3 actionPoint)
    {
        Intersect = intersect;
        MinimumTranslationVector = new Vector3(minimumTranslationVector.X, 0f, minimumTranslationVector.Z);
        NormalAxis = new Vector3(normalAxis.X, 0f, normalAxis.Z);
        ActionPoint = new Vector3(actionPoint.X, 0f, actionPoint.Z);
    }

    /// <summary>The result for two shapes that do not overlap: <c>Intersect = false</c>, all vectors zero.</summary>
    public static CollisionDetectionResult None => default;

    /// <summary>True when the interiors of the two shapes overlap.</summary>
    public bool Intersect { get; }

    /// <summary>The shortest translation (mm, X–Z plane) that, added to the first shape, leaves the two just touching.</summary>
    public Vector3 MinimumTranslationVector { get; }

    /// <summary>The unit direction of <see cref="MinimumTranslationVector"/>: from the second shape toward the first.</summary>
    public Vector3 NormalAxis { get; }

    /// <summary>A point (mm, X–Z plane) of the region where the shapes overlap.</summary>
    public Vector3 ActionPoint { get; }

    /// <summary>The penetration depth in mm: the length of <see cref="MinimumTranslationVector"/> (0 when apart).</summary>
    public float Depth => MinimumTranslationVector.Length();

    /// <summary>The same contact seen with the two shapes swapped: translation and normal negated, action point kept.</summary>
    /// <returns>The swapped result; <see cref="None"/> stays <see cref="None"/>.</returns>
    public CollisionDetectionResult Swapped() => Intersect
        ? new CollisionDetectionResult(true, -MinimumTranslationVector, -NormalAxis, ActionPoint)
        : this;

    /// <summary>A result from plane quantities (X = world X, Y = world Z): <see cref="None"/> when they do not intersect.</summary>
    internal static CollisionDetectionResult InPlane(bool intersect, Vector2 mtv, Vector2 normal, Vector2 actionPoint) =>
        intersect ? new(true, XZPlane.ToWorld(mtv), XZPlane.ToWorld(normal), XZPlane.ToWorld(actionPoint)) : None;

    /// <summary>Builds an intersecting result from plane quantities (X = world X, Y = world Z).</summary>
    internal static CollisionDetectionResult FromPlane(Vector2 normal, float depth, Vector2 actionPoint) =>
        new(true, XZPlane.ToWorld(normal * depth), XZPlane.ToWorld(normal), XZPlane.ToWorld(actionPoint));

    /// <inheritdoc />
    public bool Equals(CollisionDetectionResult other) =>
        Intersect == other.Intersect
        && MinimumTranslationVector == other.MinimumTranslationVector
        && NormalAxis == other.NormalAxis
        && ActionPoint == other.ActionPoint;

    /// <inheritdoc />
    public override bool Equals(object? obj) => obj is CollisionDetectionResult other && Equals(other);

    /// <inheritdoc />
    public override int GetHashCode() => HashCode.Combine(Intersect, MinimumTranslationVector, NormalAxis, ActionPoint);

    /// <summary>Compares two results component by component.</summary>
    public static bool operator ==(CollisionDetectionResult left, CollisionDetectionResult right) => left.Equals(right);

    /// <summary>Compares two results component by component.</summary>
    public static bool operator !=(CollisionDetectionResult left, CollisionDetectionResult right) => !left.Equals(right);

    /// <inheritdoc />
    public override string ToString() => Intersect
        ? $"Intersect mtv=({MinimumTranslationVector.X}, {MinimumTranslationVector.Z}) normal=({NormalAxis.X}, {NormalAxis.Z}) at ({ActionPoint.X}, {ActionPoint.Z})"
        : "Apart";
}
