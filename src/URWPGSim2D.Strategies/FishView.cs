namespace URWPGSim2D.Strategies;

/// <summary>What a strategy sees of one fish (mm, rad, X = world X, Y = world Z).</summary>
/// <param name="Index">Fish index in the match (the trace's fishN).</param>
/// <param name="Team">Team 0 (attacks the right goal, +X) or 1 (attacks the left goal).</param>
/// <param name="Position">Centre of the body rectangle, mm.</param>
/// <param name="Heading">Body direction, rad from +X toward +Z.</param>
/// <param name="Speed">Forward speed, mm/s.</param>
/// <param name="AngularSpeed">Angular speed, rad/s (positive turns toward +Z).</param>
/// <param name="BodyLength">Body length L, mm; the head tip is (L/2 + head) ahead of the position.</param>
/// <param name="HeadLength">Head length, mm.</param>
/// <param name="Decision">The decision the fish is executing.</param>
public readonly record struct FishView(
    int Index, int Team, Vector2 Position, float Heading, float Speed, float AngularSpeed,
    float BodyLength, float HeadLength, Decision Decision)
{
    /// <summary>Body width, mm (45 for the reference fish).</summary>
    public float Width { get; init; } = 45f;

    /// <summary>Angle of tail joint 1 (nearest the body) from the body axis, rad.</summary>
    public float Joint1 { get; init; }

    /// <summary>Angle of tail joint 2 from the body axis, rad.</summary>
    public float Joint2 { get; init; }

    /// <summary>Angle of tail joint 3 from the body axis, rad.</summary>
    public float Joint3 { get; init; }

    /// <summary>Length of tail segment 1, mm (88 for the reference fish).</summary>
    public float TailLength1 { get; init; } = 88f;

    /// <summary>Length of tail segment 2, mm (66 for the reference fish).</summary>
    public float TailLength2 { get; init; } = 66f;

    /// <summary>Length of tail segment 3, mm (55 for the reference fish).</summary>
    public float TailLength3 { get; init; } = 55f;
}
