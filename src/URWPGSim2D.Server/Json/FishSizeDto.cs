using System.Text.Json.Serialization;

namespace URWPGSim2D.Server.Json;

/// <summary>
/// The optional <c>size</c> object of a fish SHAPE, exactly as written: body length × width,
/// head length and the three tail segment lengths, mm. When the object is present every field
/// is required (<see cref="FishJson"/> checks them; the library checks the values).
/// </summary>
internal sealed class FishSizeDto
{
    /// <summary>Body rectangle length L along the fish axis, mm (&gt; 0).</summary>
    [JsonPropertyName("length")]
    public float? Length { get; init; }

    /// <summary>Body rectangle width W across the fish axis, mm (&gt; 0).</summary>
    [JsonPropertyName("width")]
    public float? Width { get; init; }

    /// <summary>Head length H in front of the body rectangle, mm (&gt; 0).</summary>
    [JsonPropertyName("head")]
    public float? Head { get; init; }

    /// <summary>Tail segment lengths [L1, L2, L3], mm (each &gt; 0).</summary>
    [JsonPropertyName("joints")]
    public float[]? Joints { get; init; }
}
