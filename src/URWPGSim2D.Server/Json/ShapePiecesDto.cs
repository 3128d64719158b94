using System.Text.Json.Serialization;
using URWPGSim2D.Collision.Shapes;

namespace URWPGSim2D.Server.Json;

/// <summary>
/// One element of the <c>shapes</c> output: the exact collision pieces of one input SHAPE in
/// world coordinates, mm. <c>type</c> comes first and says which fields follow (absent fields
/// are omitted): circle — center, radius, outer; aabb and kdop8 — min, max, vertices, outer;
/// polygon — vertices, outer; segment — a, b, vertices, outer; fish — leaves, bounds.
/// Vertices are counter-clockwise in (x, z) coordinates, as the library stores them.
/// </summary>
internal sealed class ShapePiecesDto
{
    /// <summary>The SHAPE type: circle, aabb, kdop8, polygon, segment or fish.</summary>
    [JsonPropertyName("type")]
    public required string Type { get; init; }

    /// <summary>circle: the centre [x, z].</summary>
    [JsonPropertyName("center")]
    public float[]? Center { get; init; }

    /// <summary>circle: the radius.</summary>
    [JsonPropertyName("radius")]
    public float? Radius { get; init; }

    /// <summary>aabb: the lower corner [x, z]; kdop8: the four tightened lower slab values.</summary>
    [JsonPropertyName("min")]
    public float[]? Min { get; init; }

    /// <summary>aabb: the upper corner [x, z]; kdop8: the four tightened upper slab values.</summary>
    [JsonPropertyName("max")]
    public float[]? Max { get; init; }

    /// <summary>segment: the first end point [x, z].</summary>
    [JsonPropertyName("a")]
    public float[]? A { get; init; }

    /// <summary>segment: the second end point [x, z].</summary>
    [JsonPropertyName("b")]
    public float[]? B { get; init; }

    /// <summary>aabb, kdop8, polygon, segment: the polygon the narrow phase tests, [[x, z], ...].</summary>
    [JsonPropertyName("vertices")]
    public float[][]? Vertices { get; init; }

    /// <summary>Every shape except the fish: its outer (bounding) circle.</summary>
    [JsonPropertyName("outer")]
    public CircleDto? Outer { get; init; }

    /// <summary>fish: the eight leaf polygons.</summary>
    [JsonPropertyName("leaves")]
    public FishLeavesDto? Leaves { get; init; }

    /// <summary>fish: the bounding circles of its tree.</summary>
    [JsonPropertyName("bounds")]
    public FishBoundsDto? Bounds { get; init; }

    /// <summary>The pieces of one input SHAPE.</summary>
    /// <param name="shape">The validated SHAPE.</param>
    /// <returns>The output element.</returns>
    public static ShapePiecesDto From(InputShape shape)
    {
        if (shape.IsFish)
        {
            return new ShapePiecesDto
            {
                Type = ShapeJson.FishType,
                Leaves = FishLeavesDto.From(shape.Fish),
                Bounds = FishBoundsDto.From(shape.Fish),
            };
        }

        ref readonly Shape s = ref shape.Shape;
        var outer = CircleDto.From(s.BoundingCircle);
        return s.Kind switch
        {
            ShapeKind.Circle => new ShapePiecesDto
            {
                Type = ShapeJson.CircleType,
                Center = OutputNumbers.Point(s.AsCircle().Center),
                Radius = OutputNumbers.Clean(s.AsCircle().Radius),
                Outer = outer,
            },
            ShapeKind.Aabb => new ShapePiecesDto
            {
                Type = ShapeJson.AabbType,
                Min = OutputNumbers.Point(s.AsAabb().Min),
                Max = OutputNumbers.Point(s.AsAabb().Max),
                Vertices = OutputNumbers.Points(Corners(s.AsAabb())),
                Outer = outer,
            },
            ShapeKind.KDop8 => new ShapePiecesDto
            {
                Type = ShapeJson.KDop8Type,
                Min = Slabs(s.AsKDop8(), max: false),
                Max = Slabs(s.AsKDop8(), max: true),
                Vertices = OutputNumbers.Points(s.AsKDop8().Vertices),
                Outer = outer,
            },
            ShapeKind.Polygon => new ShapePiecesDto
            {
                Type = ShapeJson.PolygonType,
                Vertices = OutputNumbers.Points(s.AsPolygon().Vertices),
                Outer = outer,
            },
            ShapeKind.Segment => new ShapePiecesDto
            {
                Type = ShapeJson.SegmentType,
                A = OutputNumbers.Point(s.AsSegment().A),
                B = OutputNumbers.Point(s.AsSegment().B),
                Vertices = OutputNumbers.Points([s.AsSegment().A, s.AsSegment().B]),
                Outer = outer,
            },
            _ => throw new InvalidOperationException($"unhandled shape kind {s.Kind}"),
        };
    }

    /// <summary>The four corners of a box, counter-clockwise in (x, z) from <see cref="Aabb.Min"/>: min, (max x, min z), max, (min x, max z).</summary>
    /// <param name="box">The box.</param>
    /// <returns>The corners.</returns>
    public static Vector2[] Corners(in Aabb box) =>
        [box.Min, new Vector2(box.Max.X, box.Min.Y), box.Max, new Vector2(box.Min.X, box.Max.Y)];

    private static float[] Slabs(in KDop8 kdop, bool max)
    {
        var values = new float[4];
        for (int i = 0; i < 4; i++)
        {
            values[i] = OutputNumbers.Clean(max ? kdop.GetMax(i) : kdop.GetMin(i));
        }

        return values;
    }
}
