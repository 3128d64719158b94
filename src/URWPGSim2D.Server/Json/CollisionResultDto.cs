using System.Text.Json.Serialization;
using URWPGSim2D.Collision;

namespace URWPGSim2D.Server.Json;

/// <summary>
/// One element of the <c>collide</c> output: a <see cref="CollisionDetectionResult"/> with each
/// vector written as [x, z] (its X and Z; Y is always 0), mm. Properties are written in
/// declaration order. This is the element of a pair without a fish, unchanged since before fish
/// existed; a pair with a fish is written as <see cref="FishCollisionResultDto"/>.
/// </summary>
internal sealed class CollisionResultDto
{
    /// <summary>Whether the interiors overlap (touching is not overlapping).</summary>
    [JsonPropertyName("intersect")]
    public required bool Intersect { get; init; }

    /// <summary>The minimum translation vector [x, z] that moves <c>a</c> out of <c>b</c>, mm; [0, 0] when apart.</summary>
    [JsonPropertyName("mtv")]
    public required float[] Mtv { get; init; }

    /// <summary>The unit normal [x, z] from <c>b</c> toward <c>a</c>; [0, 0] when apart.</summary>
    [JsonPropertyName("normal")]
    public required float[] Normal { get; init; }

    /// <summary>A point [x, z] of the overlap region, mm; [0, 0] when apart.</summary>
    [JsonPropertyName("actionPoint")]
    public required float[] ActionPoint { get; init; }

    /// <summary>Copies a library result; negative zeros are written as 0.</summary>
    /// <param name="result">The result of <see cref="CollisionDetector.Detect(in Collision.Shapes.Shape, in Collision.Shapes.Shape)"/>.</param>
    /// <returns>The output element.</returns>
    public static CollisionResultDto From(in CollisionDetectionResult result) => new()
    {
        Intersect = result.Intersect,
        Mtv = [Clean(result.MinimumTranslationVector.X), Clean(result.MinimumTranslationVector.Z)],
        Normal = [Clean(result.NormalAxis.X), Clean(result.NormalAxis.Z)],
        ActionPoint = [Clean(result.ActionPoint.X), Clean(result.ActionPoint.Z)],
    };

    // −0 == 0, so this maps −0 to +0 and leaves every other value unchanged.
    private static float Clean(float value) => value == 0f ? 0f : value;
}
