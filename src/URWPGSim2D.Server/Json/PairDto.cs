using System.Text.Json.Serialization;

namespace URWPGSim2D.Server.Json;

/// <summary>One element of the <c>collide</c> input: the shape <c>a</c> (moved by the MTV) and the shape <c>b</c>.</summary>
internal sealed class PairDto
{
    /// <summary>The first shape: the result's MTV moves it, its normal points toward it.</summary>
    [JsonPropertyName("a")]
    public ShapeDto? A { get; init; }

    /// <summary>The second shape.</summary>
    [JsonPropertyName("b")]
    public ShapeDto? B { get; init; }
}
