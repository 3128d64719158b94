namespace URWPGSim2D.Engine.Scenario;

/// <summary>A validated scenario file (mm, rad, mm/s; vectors are [x, z]).</summary>
public sealed record ScenarioDefinition
{
    /// <summary>Field length along X, mm.</summary>
    public float FieldLength { get; init; } = 3000f;

    /// <summary>Field width along Z, mm.</summary>
    public float FieldWidth { get; init; } = 2000f;

    /// <summary>Whether the four goal blocks are in place.</summary>
    public bool GoalBlocks { get; init; } = true;

    /// <summary>Cycles to play (100 ms each).</summary>
    public int Cycles { get; init; } = 3000;

    /// <summary>Noise generator seed.</summary>
    public ulong Seed { get; init; } = 1;

    /// <summary>Whether the reference's noise is on.</summary>
    public bool Noise { get; init; } = true;

    /// <summary>The fish, by index.</summary>
    public IReadOnlyList<FishDefinition> Fish { get; init; } = [];

    /// <summary>The balls, by index.</summary>
    public IReadOnlyList<BallDefinition> Balls { get; init; } = [];

    /// <summary>The obstacles, by index.</summary>
    public IReadOnlyList<ObstacleDefinition> Obstacles { get; init; } = [];

    /// <summary>The competition item played on this layout, or null for the plain goal rules.</summary>
    public IScenarioItem? Item { get; init; }

    /// <summary>Points of each ball in the item (empty: balls have no value).</summary>
    public IReadOnlyList<double> BallValues { get; init; } = [];

    /// <summary>Whether the scenario file gave the fish positions (an item with random start poses then keeps them).</summary>
    public bool FishOverridden { get; init; }

    /// <summary>The item's marked regions (goal boxes, holes, parking places).</summary>
    public IReadOnlyList<Trace.TraceZone> Zones { get; init; } = [];
}

/// <summary>A fish of a scenario.</summary>
/// <param name="Team">0 or 1.</param>
/// <param name="Position">Body centre, mm.</param>
/// <param name="Heading">rad.</param>
/// <param name="Strategy">Built-in strategy name: idle, chase-ball, fixed, or demo (the item's demo strategy).</param>
/// <param name="Decision">The decision of a fixed strategy.</param>
/// <param name="TailPhase">The fish's own tail-wave phase p, rad.</param>
public sealed record FishDefinition(int Team, Vector2 Position, float Heading, string Strategy, Decision Decision, float TailPhase = 0f);

/// <summary>A ball of a scenario.</summary>
/// <param name="Position">Centre, mm.</param>
/// <param name="Velocity">mm/s.</param>
/// <param name="Radius">mm.</param>
public sealed record BallDefinition(Vector2 Position, Vector2 Velocity, float Radius);

/// <summary>An obstacle of a scenario.</summary>
/// <param name="Kind">Rectangle or round.</param>
/// <param name="Center">mm.</param>
/// <param name="Length">Rectangle length along its heading, mm.</param>
/// <param name="Width">Rectangle width, mm.</param>
/// <param name="Heading">Rectangle direction, rad.</param>
/// <param name="Radius">Round radius, mm.</param>
public sealed record ObstacleDefinition(ObstacleKind Kind, Vector2 Center, float Length, float Width, float Heading, float Radius);
