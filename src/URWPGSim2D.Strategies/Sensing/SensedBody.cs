namespace URWPGSim2D.Strategies;

/// <summary>One body of the match as a <see cref="FieldSensor"/> names it: a kind and its index in the snapshot.</summary>
/// <param name="Kind">Border, obstacle, ball or fish (<see cref="SensedKind.None"/>: no body).</param>
/// <param name="Index">The index among bodies of that kind (a border: 0 top, 1 right, 2 bottom, 3 left).</param>
public readonly record struct SensedBody(SensedKind Kind, int Index)
{
    /// <summary>No body (<c>default</c>): what a query that finds nothing answers.</summary>
    public static SensedBody None => default;

    /// <summary>Whether this names a body (its kind is not <see cref="SensedKind.None"/>).</summary>
    public bool Exists => Kind != SensedKind.None;

    /// <summary>A field border.</summary>
    /// <param name="index">0 top (Z = −Width/2), 1 right, 2 bottom, 3 left.</param>
    /// <returns>The border.</returns>
    public static SensedBody Wall(int index) => new(SensedKind.Wall, index);

    /// <summary>An obstacle.</summary>
    /// <param name="index">Its index in <see cref="MatchSnapshot.Obstacles"/>.</param>
    /// <returns>The obstacle.</returns>
    public static SensedBody Obstacle(int index) => new(SensedKind.Obstacle, index);

    /// <summary>A ball.</summary>
    /// <param name="index">Its index in <see cref="MatchSnapshot.Balls"/>.</param>
    /// <returns>The ball.</returns>
    public static SensedBody Ball(int index) => new(SensedKind.Ball, index);

    /// <summary>A fish.</summary>
    /// <param name="index">Its index in <see cref="MatchSnapshot.Fish"/>.</param>
    /// <returns>The fish.</returns>
    public static SensedBody Fish(int index) => new(SensedKind.Fish, index);

    /// <inheritdoc />
    public override string ToString() => Exists ? $"{Kind.ToString().ToLowerInvariant()} {Index}" : "none";
}
