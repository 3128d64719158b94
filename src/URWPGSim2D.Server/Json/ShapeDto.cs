using System.Text.Json.Serialization;

namespace URWPGSim2D.Server.Json;

/// <summary>
/// One SHAPE object of the input, exactly as written: <c>type</c> says which of the other
/// fields apply. Every field is optional here; <see cref="ShapeJson"/> checks the fields the
/// type needs and builds the library shape. Coordinates are (x, z) in mm. Unknown fields are ignored.
/// </summary>
internal sealed class ShapeDto
{
    /// <summary>The shape kind: circle, aabb, kdop8, polygon, segment or fish.</summary>
    [JsonPropertyName("type")]
    public string? Type { get; init; }

    /// <summary>circle: the centre [x, z], mm.</summary>
    [JsonPropertyName("center")]
    public float[]? Center { get; init; }

    /// <summary>circle: the radius, mm (&gt; 0).</summary>
    [JsonPropertyName("radius")]
    public float? Radius { get; init; }

    /// <summary>aabb: the lower corner [x, z]; kdop8: the four lower slab values [s0, s1, s2, s3], mm.</summary>
    [JsonPropertyName("min")]
    public float[]? Min { get; init; }

    /// <summary>aabb: the upper corner [x, z]; kdop8: the four upper slab values [s0, s1, s2, s3], mm.</summary>
    [JsonPropertyName("max")]
    public float[]? Max { get; init; }

    /// <summary>polygon: the vertices [[x, z], ...] of a convex polygon in either winding, mm.</summary>
    [JsonPropertyName("vertices")]
    public float[]?[]? Vertices { get; init; }

    /// <summary>segment: the first end point [x, z], mm.</summary>
    [JsonPropertyName("a")]
    public float[]? A { get; init; }

    /// <summary>segment: the second end point [x, z], mm.</summary>
    [JsonPropertyName("b")]
    public float[]? B { get; init; }

    /// <summary>fish: the centre of the body rectangle [x, z], mm.</summary>
    [JsonPropertyName("position")]
    public float[]? Position { get; init; }

    /// <summary>fish: the heading θ, rad, from +X toward +Z.</summary>
    [JsonPropertyName("heading")]
    public float? Heading { get; init; }

    /// <summary>fish: the three tail joint angles [φ1, φ2, φ3], rad, each from the body axis.</summary>
    [JsonPropertyName("joints")]
    public float[]? Joints { get; init; }

    /// <summary>fish: the dimensions; absent or null for the deployed 160 × 45, head 30, joints 88 / 66 / 55.</summary>
    [JsonPropertyName("size")]
    public FishSizeDto? Size { get; init; }
}
