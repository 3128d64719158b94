using System.Text.Json.Serialization;
using URWPGSim2D.Collision.Fish;

namespace URWPGSim2D.Server.Json;

/// <summary>
/// The eight leaf polygons of a fish in the <c>shapes</c> output, keyed by camelCase
/// <see cref="FishPart"/> name in part order; each is its world vertices <c>[[x,z],...]</c>, mm,
/// counter-clockwise in (x, z) coordinates (clockwise on a screen with +Z down), as the library
/// stores them for its separating-axis tests.
/// </summary>
internal sealed class FishLeavesDto
{
    /// <summary>The left pectoral fin (4 vertices).</summary>
    [JsonPropertyName("leftPectoral")]
    public required float[][] LeftPectoral { get; init; }

    /// <summary>The body with the head (5 vertices).</summary>
    [JsonPropertyName("body")]
    public required float[][] Body { get; init; }

    /// <summary>The right pectoral fin (4 vertices).</summary>
    [JsonPropertyName("rightPectoral")]
    public required float[][] RightPectoral { get; init; }

    /// <summary>Tail segment 1 (4 vertices).</summary>
    [JsonPropertyName("tail1")]
    public required float[][] Tail1 { get; init; }

    /// <summary>Tail segment 2 (4 vertices).</summary>
    [JsonPropertyName("tail2")]
    public required float[][] Tail2 { get; init; }

    /// <summary>Tail segment 3 (4 vertices).</summary>
    [JsonPropertyName("tail3")]
    public required float[][] Tail3 { get; init; }

    /// <summary>The left lobe of the caudal fin (3 vertices).</summary>
    [JsonPropertyName("leftCaudal")]
    public required float[][] LeftCaudal { get; init; }

    /// <summary>The right lobe of the caudal fin (3 vertices).</summary>
    [JsonPropertyName("rightCaudal")]
    public required float[][] RightCaudal { get; init; }

    /// <summary>Copies the fish's current leaves.</summary>
    /// <param name="fish">The fish model.</param>
    /// <returns>The output object.</returns>
    public static FishLeavesDto From(FishModel fish) => new()
    {
        LeftPectoral = Leaf(fish, FishPart.LeftPectoral),
        Body = Leaf(fish, FishPart.Body),
        RightPectoral = Leaf(fish, FishPart.RightPectoral),
        Tail1 = Leaf(fish, FishPart.Tail1),
        Tail2 = Leaf(fish, FishPart.Tail2),
        Tail3 = Leaf(fish, FishPart.Tail3),
        LeftCaudal = Leaf(fish, FishPart.LeftCaudal),
        RightCaudal = Leaf(fish, FishPart.RightCaudal),
    };

    private static float[][] Leaf(FishModel fish, FishPart part) => OutputNumbers.Points(fish.GetLeaf(part));
}
