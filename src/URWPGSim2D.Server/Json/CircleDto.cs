using System.Text.Json.Serialization;
using URWPGSim2D.Collision.Shapes;

namespace URWPGSim2D.Server.Json;

/// <summary>A circle in the <c>shapes</c> output: <c>{"center":[x,z],"radius":r}</c>, mm (an outer circle or a bounding circle of the fish tree).</summary>
internal sealed class CircleDto
{
    /// <summary>The centre [x, z], mm.</summary>
    [JsonPropertyName("center")]
    public required float[] Center { get; init; }

    /// <summary>The radius, mm.</summary>
    [JsonPropertyName("radius")]
    public required float Radius { get; init; }

    /// <summary>Copies a library circle.</summary>
    /// <param name="circle">The circle.</param>
    /// <returns>The output object.</returns>
    public static CircleDto From(in Circle circle) => new()
    {
        Center = OutputNumbers.Point(circle.Center),
        Radius = OutputNumbers.Clean(circle.Radius),
    };
}
