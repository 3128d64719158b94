using System.Text.Json.Serialization;
using URWPGSim2D.Collision.Fish;

namespace URWPGSim2D.Server.Json;

/// <summary>
/// The bounding circles of a fish's tree in the <c>shapes</c> output: the root (whole fish), the
/// body group (body and both pectoral fins) and the tail group (three segments and the caudal fin).
/// </summary>
internal sealed class FishBoundsDto
{
    /// <summary><see cref="FishModel.Root"/>.</summary>
    [JsonPropertyName("root")]
    public required CircleDto Root { get; init; }

    /// <summary><see cref="FishModel.BodyGroup"/>.</summary>
    [JsonPropertyName("body")]
    public required CircleDto Body { get; init; }

    /// <summary><see cref="FishModel.TailGroup"/>.</summary>
    [JsonPropertyName("tail")]
    public required CircleDto Tail { get; init; }

    /// <summary>Copies the fish's current bounding circles.</summary>
    /// <param name="fish">The fish model.</param>
    /// <returns>The output object.</returns>
    public static FishBoundsDto From(FishModel fish) => new()
    {
        Root = CircleDto.From(fish.Root),
        Body = CircleDto.From(fish.BodyGroup),
        Tail = CircleDto.From(fish.TailGroup),
    };
}
