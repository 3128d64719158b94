using URWPGSim2D.Collision.Shapes;

namespace URWPGSim2D.Server.Json;

/// <summary>
/// The SHAPE objects of the input, turned into library shapes — the one place that knows the
/// shape formats (docs/cli.md). Each type reads its fields with <see cref="FieldReader"/> and
/// lets the library validate the values; every failure is a <see cref="InputException"/>
/// whose path names the field (<c>pairs[12].b.vertices</c>). To add a type: a constant, a case
/// in <see cref="Read"/>, a reader method, and its fields in <see cref="ShapeDto"/> and
/// <see cref="ShapeSchema"/>. The fish, which is not a library <see cref="Shape"/>, is read by
/// <see cref="FishJson"/>.
/// </summary>
internal static class ShapeJson
{
    /// <summary><c>{"type":"circle","center":[x,z],"radius":r}</c>.</summary>
    public const string CircleType = "circle";

    /// <summary><c>{"type":"aabb","min":[x,z],"max":[x,z]}</c>.</summary>
    public const string AabbType = "aabb";

    /// <summary><c>{"type":"kdop8","min":[s0,s1,s2,s3],"max":[s0,s1,s2,s3]}</c>.</summary>
    public const string KDop8Type = "kdop8";

    /// <summary><c>{"type":"polygon","vertices":[[x,z],...]}</c>.</summary>
    public const string PolygonType = "polygon";

    /// <summary><c>{"type":"segment","a":[x,z],"b":[x,z]}</c>.</summary>
    public const string SegmentType = "segment";

    /// <summary><c>{"type":"fish","position":[x,z],"heading":θ,"joints":[φ1,φ2,φ3]}</c>, optional <c>"size"</c> (see <see cref="FishJson"/>).</summary>
    public const string FishType = "fish";

    // Library constructor parameter → JSON field, per type (the names agree today; the tables
    // keep the mapping explicit and checked by the tests).
    private static readonly Dictionary<string, string> CircleFields = new() { ["center"] = "center", ["radius"] = "radius" };
    private static readonly Dictionary<string, string> BoxFields = new() { ["min"] = "min", ["max"] = "max" };
    private static readonly Dictionary<string, string> PolygonFields = new() { ["vertices"] = "vertices" };
    private static readonly Dictionary<string, string> SegmentFields = new() { ["a"] = "a", ["b"] = "b" };

    /// <summary>Builds the library shape or fish described by <paramref name="dto"/>.</summary>
    /// <param name="dto">The deserialized SHAPE object; null when it was absent or null.</param>
    /// <param name="path">The path of the SHAPE object, e.g. <c>pairs[3].a</c>.</param>
    /// <returns>The validated shape.</returns>
    /// <exception cref="InputException">A field is missing, has the wrong length, or holds a value the library rejects.</exception>
    public static InputShape Read(ShapeDto? dto, string path)
    {
        if (dto is null)
        {
            throw new InputException(path, FieldReader.MissingMessage);
        }

        var fields = new FieldReader(path);
        string type = fields.String(dto.Type, "type");
        return type switch
        {
            CircleType => InputShape.Of(ReadCircle(dto, fields)),
            AabbType => InputShape.Of(ReadAabb(dto, fields)),
            KDop8Type => InputShape.Of(ReadKDop8(dto, fields)),
            PolygonType => InputShape.Of(ReadPolygon(dto, fields)),
            SegmentType => InputShape.Of(ReadSegment(dto, fields)),
            FishType => InputShape.Of(FishJson.Read(dto, fields)),
            _ => throw new InputException(fields.PathOf("type"), $"unknown shape type {MessageText.Quote(type)}"),
        };
    }

    private static Shape ReadCircle(ShapeDto dto, FieldReader fields)
    {
        var center = fields.Point(dto.Center, "center");
        float radius = fields.Number(dto.Radius, "radius");
        try
        {
            return new Circle(center, radius);
        }
        catch (ArgumentException ex)
        {
            throw LibraryArgumentErrors.ToInputError(ex, fields.ObjectPath, CircleFields);
        }
    }

    private static Shape ReadAabb(ShapeDto dto, FieldReader fields)
    {
        var min = fields.Point(dto.Min, "min");
        var max = fields.Point(dto.Max, "max");
        try
        {
            return new Aabb(min, max);
        }
        catch (ArgumentException ex)
        {
            throw LibraryArgumentErrors.ToInputError(ex, fields.ObjectPath, BoxFields);
        }
    }

    private static Shape ReadKDop8(ShapeDto dto, FieldReader fields)
    {
        float[] min = fields.Slabs(dto.Min, "min");
        float[] max = fields.Slabs(dto.Max, "max");
        try
        {
            return new KDop8(min, max);
        }
        catch (ArgumentException ex)
        {
            throw LibraryArgumentErrors.ToInputError(ex, fields.ObjectPath, BoxFields);
        }
    }

    private static Shape ReadPolygon(ShapeDto dto, FieldReader fields)
    {
        var vertices = fields.Points(dto.Vertices, "vertices");
        try
        {
            return new ConvexPolygon(vertices);
        }
        catch (ArgumentException ex)
        {
            throw LibraryArgumentErrors.ToInputError(ex, fields.ObjectPath, PolygonFields);
        }
    }

    private static Shape ReadSegment(ShapeDto dto, FieldReader fields)
    {
        var a = fields.Point(dto.A, "a");
        var b = fields.Point(dto.B, "b");
        try
        {
            return new Segment(a, b);
        }
        catch (ArgumentException ex)
        {
            throw LibraryArgumentErrors.ToInputError(ex, fields.ObjectPath, SegmentFields);
        }
    }
}
