using System.Text.Json.Serialization;
using URWPGSim2D.Collision.Fish;
using URWPGSim2D.Engine.Trace;

namespace URWPGSim2D.Server.Json;

/// <summary>
/// One element of the <c>collide</c> output for a pair in which at least one side is a fish:
/// the four fields of <see cref="CollisionResultDto"/>, in the same order and form, then
/// <c>partA</c> and <c>partB</c>, which are always written (null for a side that is not a fish,
/// and for both sides when the pair does not intersect).
/// </summary>
internal sealed class FishCollisionResultDto
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

    /// <summary>The leaf of fish <c>a</c> in the deepest contact (camelCase <see cref="FishPart"/> name); null when <c>a</c> is not a fish or there is no contact.</summary>
    [JsonPropertyName("partA")]
    [JsonIgnore(Condition = JsonIgnoreCondition.Never)]
    public required string? PartA { get; init; }

    /// <summary>The leaf of fish <c>b</c> in the deepest contact; null when <c>b</c> is not a fish or there is no contact.</summary>
    [JsonPropertyName("partB")]
    [JsonIgnore(Condition = JsonIgnoreCondition.Never)]
    public required string? PartB { get; init; }

    /// <summary>Copies a fish contact; negative zeros are written as 0.</summary>
    /// <param name="contact">The result of a <see cref="FishCollision"/> query (MTV moves a).</param>
    /// <returns>The output element.</returns>
    public static FishCollisionResultDto From(in FishContact contact)
    {
        var plain = CollisionResultDto.From(contact.Result);
        return new FishCollisionResultDto
        {
            Intersect = plain.Intersect,
            Mtv = plain.Mtv,
            Normal = plain.Normal,
            ActionPoint = plain.ActionPoint,
            PartA = FishPartNames.OfOptional(contact.PartA),
            PartB = FishPartNames.OfOptional(contact.PartB),
        };
    }
}
