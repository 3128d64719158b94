using System.Numerics;

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
    float BodyLength, float HeadLength, Decision Decision);
