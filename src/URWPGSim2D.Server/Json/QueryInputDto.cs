using System.Text.Json.Serialization;

namespace URWPGSim2D.Server.Json;

/// <summary>The <c>query</c> input document: the shapes, then the questions asked about them by index.</summary>
internal sealed class QueryInputDto
{
    /// <summary>The SHAPE objects, numbered from 0.</summary>
    [JsonPropertyName("shapes")]
    public ShapeDto?[]? Shapes { get; init; }

    /// <summary>The queries, answered in order.</summary>
    [JsonPropertyName("queries")]
    public QueryDto?[]? Queries { get; init; }
}

/// <summary>One query: <c>type</c> says which of the other fields apply.</summary>
internal sealed class QueryDto
{
    /// <summary>distance, ray, cast or overlap.</summary>
    [JsonPropertyName("type")]
    public string? Type { get; init; }

    /// <summary>distance: the first shape's index.</summary>
    [JsonPropertyName("a")]
    public int? A { get; init; }

    /// <summary>distance: the second shape's index.</summary>
    [JsonPropertyName("b")]
    public int? B { get; init; }

    /// <summary>ray: the start [x, z], mm.</summary>
    [JsonPropertyName("from")]
    public float[]? From { get; init; }

    /// <summary>ray: the end [x, z], mm.</summary>
    [JsonPropertyName("to")]
    public float[]? To { get; init; }

    /// <summary>cast: the moving shape's index.</summary>
    [JsonPropertyName("shape")]
    public int? Shape { get; init; }

    /// <summary>cast: the whole move [x, z], mm.</summary>
    [JsonPropertyName("translation")]
    public float[]? Translation { get; init; }

    /// <summary>cast: the index of the shape in the way.</summary>
    [JsonPropertyName("against")]
    public int? Against { get; init; }

    /// <summary>overlap: the box.</summary>
    [JsonPropertyName("aabb")]
    public QueryBoxDto? Aabb { get; init; }
}

/// <summary>The box of an overlap query.</summary>
internal sealed class QueryBoxDto
{
    /// <summary>The lower corner [x, z], mm.</summary>
    [JsonPropertyName("min")]
    public float[]? Min { get; init; }

    /// <summary>The upper corner [x, z], mm.</summary>
    [JsonPropertyName("max")]
    public float[]? Max { get; init; }
}
