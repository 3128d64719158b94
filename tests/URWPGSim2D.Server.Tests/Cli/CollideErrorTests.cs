using static URWPGSim2D.Server.Tests.Cli.ShapeText;

namespace URWPGSim2D.Server.Tests.Cli;

/// <summary>
/// Every kind of bad input gives exactly one stderr line naming the pair and field, exit code 2,
/// and nothing on stdout.
/// </summary>
public sealed class CollideErrorTests
{
    private static readonly string Ok = Circle(0, 0, 1);

    public static TheoryData<string, string> BadShapes() => new()
    {
        // Non-finite numbers: the named literals and values beyond single precision.
        { """{"type":"circle","center":["NaN",0],"radius":1}""", "pairs[0].a.center: must have finite coordinates, got [NaN, 0]" },
        { """{"type":"circle","center":[0,0],"radius":"Infinity"}""", "pairs[0].a.radius: must be a finite number, got Infinity" },
        { """{"type":"circle","center":[0,0],"radius":1e39}""", "pairs[0].a.radius: must be a finite number, got Infinity" },
        { """{"type":"aabb","min":[0,"-Infinity"],"max":[1,1]}""", "pairs[0].a.min: must have finite coordinates, got [0, -Infinity]" },
        { """{"type":"kdop8","min":[0,0,0,"-Infinity"],"max":[1,1,1,1]}""", "pairs[0].a.min[3]: must be a finite number, got -Infinity" },
        { """{"type":"polygon","vertices":[[0,0],[10,0],[1e39,10]]}""", "pairs[0].a.vertices[2]: must have finite coordinates, got [Infinity, 10]" },
        { """{"type":"segment","a":[0,0],"b":[0,"NaN"]}""", "pairs[0].a.b: must have finite coordinates, got [0, NaN]" },

        // Radius ≤ 0.
        { Circle(0, 0, -5), "pairs[0].a.radius: must be > 0, got -5" },
        { Circle(0, 0, 0), "pairs[0].a.radius: must be > 0, got 0" },

        // min > max.
        { Aabb(5, 0, 3, 1), "pairs[0].a.min: min x (5) is greater than max x (3)" },
        { Aabb(0, 2, 3, 1), "pairs[0].a.min: min z (2) is greater than max z (1)" },
        { KDop8([0, 0, 4, 0], [1, 1, 1, 1]), "pairs[0].a.min: min[2] (4) is greater than max[2] (1)" },

        // Polygons: too few, repeated, collinear, not convex.
        { Polygon((0, 0), (1, 0)), "pairs[0].a.vertices: polygon needs at least 3 vertices, got 2" },
        { """{"type":"polygon","vertices":[]}""", "pairs[0].a.vertices: polygon needs at least 3 vertices, got 0" },
        { Polygon((1, 2), (5, 0), (1, 2), (0, 5)), "pairs[0].a.vertices: polygon repeats vertex [1, 2] (indices 0 and 2)" },
        { Polygon((0, 0), (10, 0), (20, 0)), "pairs[0].a.vertices: polygon is degenerate: its vertices are collinear" },
        { Polygon((0, 0), (10, 0), (10, 10), (5, 2)), "pairs[0].a.vertices: polygon is not convex" },

        // 8-DOP slabs that share no point: the diagonal slab lies beyond the unit box.
        { KDop8([0, 0, 100, 0], [1, 1, 101, 1]), "pairs[0].a.min: 8-DOP slabs have no point in common (the diagonal slabs miss the box)" },

        // Segment of zero length.
        { Segment(1, 1, 1, 1), "pairs[0].a.b: segment has zero length: both ends are [1, 1]" },

        // Unknown or missing type (names are case-sensitive).
        { """{"type":"triangle"}""", "pairs[0].a.type: unknown shape type \"triangle\"" },
        { """{"type":"Circle","center":[0,0],"radius":1}""", "pairs[0].a.type: unknown shape type \"Circle\"" },
        { """{"type":"tri\nangle"}""", "pairs[0].a.type: unknown shape type \"tri\\nangle\"" },
        { """{"center":[0,0],"radius":1}""", "pairs[0].a.type: required field is missing or null" },

        // Missing or null fields.
        { """{"type":"circle","center":[0,0]}""", "pairs[0].a.radius: required field is missing or null" },
        { """{"type":"circle","center":null,"radius":1}""", "pairs[0].a.center: required field is missing or null" },
        { """{"type":"aabb","min":[0,0]}""", "pairs[0].a.max: required field is missing or null" },
        { """{"type":"kdop8","max":[1,1,1,1]}""", "pairs[0].a.min: required field is missing or null" },
        { """{"type":"polygon"}""", "pairs[0].a.vertices: required field is missing or null" },
        { """{"type":"segment","a":[1,1]}""", "pairs[0].a.b: required field is missing or null" },

        // Wrong array lengths.
        { """{"type":"circle","center":[1,2,3],"radius":1}""", "pairs[0].a.center: must be an array of 2 numbers [x, z], got 3" },
        { """{"type":"aabb","min":[0],"max":[1,1]}""", "pairs[0].a.min: must be an array of 2 numbers [x, z], got 1" },
        { """{"type":"kdop8","min":[0,0,0],"max":[1,1,1,1]}""", "pairs[0].a.min: must be an array of 4 numbers [s0, s1, s2, s3], got 3" },
        { """{"type":"kdop8","min":[0,0,0,0],"max":[1,1,1,1,1]}""", "pairs[0].a.max: must be an array of 4 numbers [s0, s1, s2, s3], got 5" },
        { """{"type":"polygon","vertices":[[0,0],[1],[1,1]]}""", "pairs[0].a.vertices[1]: must be an array of 2 numbers [x, z], got 1" },
        { """{"type":"polygon","vertices":[[0,0],null,[1,1]]}""", "pairs[0].a.vertices[1]: must be an array of 2 numbers [x, z], got null" },
        { """{"type":"segment","a":[],"b":[1,1]}""", "pairs[0].a.a: must be an array of 2 numbers [x, z], got 0" },

        // Well-formed values of the wrong JSON type: the column of the value's last byte, or of
        // the opening bracket of an array or object.
        { """{"type":"circle","center":[0,0],"radius":"x"}""", "pairs[0].a.radius: expected a number at line 1, column 50" },
        { """{"type":5}""", "pairs[0].a.type: expected a string at line 1, column 15" },
        { """{"type":"circle","center":{},"radius":1}""", "pairs[0].a.center: expected an array of 2 numbers [x, z] at line 1, column 33" },
        { """{"type":"circle","center":[0,true],"radius":1}""", "pairs[0].a.center[1]: expected a number at line 1, column 39" },
        { """{"type":"polygon","vertices":[[0,0],"x",[1,1]]}""", "pairs[0].a.vertices[1]: expected an array of 2 numbers [x, z] at line 1, column 45" },
        { """{"type":"polygon","vertices":{}}""", "pairs[0].a.vertices: expected an array of [x, z] points at line 1, column 36" },
        { """{"type":"aabb","min":[0,[1]],"max":[1,1]}""", "pairs[0].a.min[1]: expected a number at line 1, column 31" },
        { "[]", "pairs[0].a: expected a shape object {\"type\": ..., ...} at line 1, column 7" },
        { "null", "pairs[0].a: required field is missing or null" },
    };

    [Theory]
    [MemberData(nameof(BadShapes))]
    public void BadShapeIsReportedByPairAndField(string shape, string expectedLine)
    {
        AssertFails("[{\"a\":" + shape + ",\"b\":" + Ok + "}]", expectedLine);
    }

    [Fact]
    public void TheReportedPairIndexAndSideAreThoseOfTheBadShape()
    {
        var pairs = Enumerable.Repeat(Pair(Ok, Ok), 12).Append(Pair(Ok, Polygon((0, 0), (10, 0), (10, 10), (5, 2))));

        AssertFails(Pairs([.. pairs]), "pairs[12].b.vertices: polygon is not convex");
    }

    [Fact]
    public void NegativeRadiusInTheFourthPair()
    {
        AssertFails(Pairs(Pair(Ok, Ok), Pair(Ok, Ok), Pair(Ok, Ok), Pair(Circle(0, 0, -5), Ok)), "pairs[3].a.radius: must be > 0, got -5");
    }

    [Fact]
    public void APolygonWithTooManyVerticesIsRejected()
    {
        var vertices = new (double X, double Z)[65];
        for (int i = 0; i < vertices.Length; i++)
        {
            double angle = 2 * System.Math.PI * i / vertices.Length;
            vertices[i] = (System.Math.Round(100 * System.Math.Cos(angle), 3), System.Math.Round(100 * System.Math.Sin(angle), 3));
        }

        AssertFails(Pairs(Pair(Ok, Polygon(vertices))), "pairs[0].b.vertices: polygon has 65 vertices, at most 64 are allowed");
    }

    [Fact]
    public void TheFirstProblemInDocumentOrderIsReported()
    {
        string bad = Circle(0, 0, -1);
        AssertFails(Pairs(Pair(Ok, Ok), Pair(Ok, bad), Pair(bad, Ok), Pair(bad, bad)), "pairs[1].b.radius: must be > 0, got -1");
    }

    [Fact]
    public void AShapeErrorAfterManyGoodPairsWritesNothing()
    {
        // 500 valid pairs are computed in memory only; the bad last one must suppress all output.
        var pairs = Enumerable.Repeat(Pair(Circle(0, 0, 2), Circle(1, 0, 2)), 500).Append(Pair(Ok, """{"type":"hexagon"}"""));
        AssertFails(Pairs([.. pairs]), "pairs[500].b.type: unknown shape type \"hexagon\"");
    }

    private static readonly string Unclosed = "[{\"a\":" + Ok + ",\"b\":" + Ok + "}";

    public static TheoryData<string, string> BadDocuments() => new()
    {
        { "", "pairs: input is empty" },
        { " \n\t", "pairs: input is empty" },
        { "null", "pairs: must be an array of {\"a\": SHAPE, \"b\": SHAPE} objects, got null" },
        { "[null]", "pairs[0]: must be an object {\"a\": SHAPE, \"b\": SHAPE}, got null" },
        { "{}", "pairs: expected an array of {\"a\": SHAPE, \"b\": SHAPE} objects at line 1, column 1" },
        { "[1]", "pairs[0]: expected an object {\"a\": SHAPE, \"b\": SHAPE} at line 1, column 2" },
        { "[{\"b\":" + Ok + "}]", "pairs[0].a: required field is missing or null" },
        { "[{\"a\":" + Ok + "}]", "pairs[0].b: required field is missing or null" },
        { "[{\"a\":" + Ok + ",\"b\":null}]", "pairs[0].b: required field is missing or null" },

        // Malformed JSON: the line and column of the offending byte, the reader's reason, and the
        // path where the reader was (after the root's last element it is the next index).
        {
            "[\n  {\"a\": " + Ok + ",\n   \"b\": {\"type\": \"segment\", \"a\": [1, 1], \"b\": [1, 2,]}}\n]",
            "pairs[0].b.b[2]: malformed JSON at line 3, column 53: The JSON array contains a trailing comma at the end which is not supported in this mode. Change the reader options."
        },
        { "[{\"a\": NaN}]", "pairs[0].a: malformed JSON at line 1, column 8: 'N' is an invalid start of a value." },
        // The unclosed array is reported at the end of the input: one past its last byte.
        { Unclosed, $"pairs[1]: malformed JSON at line 1, column {Unclosed.Length + 1}: Expected depth to be zero at the end of the JSON payload. There is an open JSON object or array that should be closed." },
        { "[{a: 1}]", "pairs[0]: malformed JSON at line 1, column 3: 'a' is an invalid start of a property name. Expected a '\"'." },
        { "[] // comment", "pairs[0]: malformed JSON at line 1, column 4: '/' is invalid after a single JSON value. Expected end of data." },
    };

    [Theory]
    [MemberData(nameof(BadDocuments))]
    public void BadDocumentIsReportedWithItsPath(string json, string expectedLine)
    {
        AssertFails(json, expectedLine);
    }

    [Fact]
    public void MissingFileIsReportedByName()
    {
        string missing = System.IO.Path.Combine(System.IO.Path.GetTempPath(), "urwpgsim2d-no-such-file-7f3a.json");

        var run = CliRun.Of(string.Empty, "collide", missing);

        AssertOneLineFailure(run, missing + ": file not found");
    }

    [Fact]
    public void MissingDirectoryIsReportedByName()
    {
        string missing = System.IO.Path.Combine(System.IO.Path.GetTempPath(), "urwpgsim2d-no-such-dir-7f3a", "pairs.json");

        var run = CliRun.Of(string.Empty, "collide", missing);

        AssertOneLineFailure(run, missing + ": file not found");
    }

    [Fact]
    public void AnUnreadableFileIsReportedByName()
    {
        // A directory cannot be read as a file (whatever the user's permissions).
        string directory = System.IO.Path.Combine(System.IO.Path.GetTempPath(), $"urwpgsim2d-dir-{System.Guid.NewGuid():N}");
        System.IO.Directory.CreateDirectory(directory);
        try
        {
            var run = CliRun.Of(string.Empty, "collide", directory);

            AssertOneLineFailure(run, $"{directory}: cannot read file: Access to the path '{directory}' is denied.");
        }
        finally
        {
            System.IO.Directory.Delete(directory);
        }
    }

    internal static void AssertOneLineFailure(CliRun run, string expectedLine)
    {
        Assert.Equal(2, run.ExitCode);
        Assert.Equal(string.Empty, run.Stdout);
        Assert.Equal(expectedLine + "\n", run.Stderr);
    }

    private static void AssertFails(string json, string expectedLine) => AssertOneLineFailure(CliRun.Collide(json), expectedLine);
}
