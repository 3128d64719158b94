using static URWPGSim2D.Server.Tests.Cli.ShapeText;

namespace URWPGSim2D.Server.Tests.Cli;

/// <summary>
/// Bad fish SHAPEs and bad <c>shapes</c> documents: one stderr line naming the index and the
/// field, exit code 2, nothing on stdout — through <c>shapes</c> (root <c>shapes</c>) and
/// <c>collide</c> (root <c>pairs</c>).
/// </summary>
public sealed class FishInputErrorTests
{
    private const string Pose = "\"position\":[0,0],\"heading\":0,\"joints\":[0,0,0]";

    public static TheoryData<string, string> BadFish() => new()
    {
        // Missing fields and wrong lengths.
        { """{"type":"fish","heading":0,"joints":[0,0,0]}""", "position: required field is missing or null" },
        { """{"type":"fish","position":[0,0],"joints":[0,0,0]}""", "heading: required field is missing or null" },
        { """{"type":"fish","position":[0,0],"heading":0}""", "joints: required field is missing or null" },
        { """{"type":"fish","position":[0,0,0],"heading":0,"joints":[0,0,0]}""", "position: must be an array of 2 numbers [x, z], got 3" },
        { """{"type":"fish","position":[0,0],"heading":0,"joints":[0,0]}""", "joints: must be an array of 3 numbers [φ1, φ2, φ3], got 2" },
        { """{"type":"fish","position":[0,0],"heading":0,"joints":[]}""", "joints: must be an array of 3 numbers [φ1, φ2, φ3], got 0" },

        // Non-finite pose values (the library's checks, mapped to the fields).
        { """{"type":"fish","position":["NaN",0],"heading":0,"joints":[0,0,0]}""", "position: must have finite coordinates, got [NaN, 0]" },
        { """{"type":"fish","position":[0,0],"heading":"Infinity","joints":[0,0,0]}""", "heading: must be a finite number, got Infinity" },
        { """{"type":"fish","position":[0,0],"heading":0,"joints":[0,"NaN",0]}""", "joints[1]: must be a finite number, got NaN" },
        { """{"type":"fish","position":[0,0],"heading":0,"joints":[0,0,1e39]}""", "joints[2]: must be a finite number, got Infinity" },

        // The size object: every field required, values > 0, a non-degenerate caudal fin.
        { "{\"type\":\"fish\"," + Pose + ",\"size\":{\"length\":160,\"width\":0,\"head\":30,\"joints\":[88,66,55]}}", "size.width: must be > 0, got 0" },
        { "{\"type\":\"fish\"," + Pose + ",\"size\":{\"length\":-1,\"width\":45,\"head\":30,\"joints\":[88,66,55]}}", "size.length: must be > 0, got -1" },
        { "{\"type\":\"fish\"," + Pose + ",\"size\":{\"length\":160,\"width\":45,\"head\":\"Infinity\",\"joints\":[88,66,55]}}", "size.head: must be a finite number, got Infinity" },
        { "{\"type\":\"fish\"," + Pose + ",\"size\":{\"length\":160,\"width\":45,\"head\":30,\"joints\":[88,-66,55]}}", "size.joints[1]: must be > 0, got -66" },
        { "{\"type\":\"fish\"," + Pose + ",\"size\":{\"length\":160,\"width\":45,\"head\":30,\"joints\":[88,66,1666.67]}}", "size.joints[2]: joint3 = 1666.67 makes the LeftCaudal leaf polygon degenerate (its vertices are collinear)" },
        { "{\"type\":\"fish\"," + Pose + ",\"size\":{\"width\":45,\"head\":30,\"joints\":[88,66,55]}}", "size.length: required field is missing or null" },
        { "{\"type\":\"fish\"," + Pose + ",\"size\":{\"length\":160,\"width\":45,\"joints\":[88,66,55]}}", "size.head: required field is missing or null" },
        { "{\"type\":\"fish\"," + Pose + ",\"size\":{\"length\":160,\"width\":45,\"head\":30}}", "size.joints: required field is missing or null" },
        { "{\"type\":\"fish\"," + Pose + ",\"size\":{\"length\":160,\"width\":45,\"head\":30,\"joints\":[88,66,55,44]}}", "size.joints: must be an array of 3 numbers [L1, L2, L3], got 4" },

        // The pose is checked before the size.
        { """{"type":"fish","position":[0,0],"heading":"NaN","joints":[0,0,0],"size":{"length":0,"width":45,"head":30,"joints":[88,66,55]}}""", "heading: must be a finite number, got NaN" },
    };

    [Theory]
    [MemberData(nameof(BadFish))]
    public void ABadFishInShapesNamesTheIndexAndField(string fish, string expected)
    {
        // Three good shapes first, so the index is 3.
        string json = Shapes(Fish(0, 0, 0), Circle(0, 0, 1), Fish(1, 2, 3, 0.1, 0.2, 0.3, [200, 50, 40, 90, 70, 60]), fish);

        CollideErrorTests.AssertOneLineFailure(CliRun.Shapes(json), "shapes[3]." + expected);
    }

    [Theory]
    [MemberData(nameof(BadFish))]
    public void ABadFishInCollideNamesThePairSideAndField(string fish, string expected)
    {
        string json = Pairs(Pair(Fish(0, 0, 0), Circle(0, 0, 1)), Pair(Circle(0, 0, 1), fish));

        CollideErrorTests.AssertOneLineFailure(CliRun.Collide(json), "pairs[1].b." + expected);
    }

    [Fact]
    public void TheBriefsExamples()
    {
        string twoJoints = """{"type":"fish","position":[0,0],"heading":0,"joints":[0,0]}""";
        string zeroWidth = "{\"type\":\"fish\"," + Pose + ",\"size\":{\"length\":160,\"width\":0,\"head\":30,\"joints\":[88,66,55]}}";

        CollideErrorTests.AssertOneLineFailure(
            CliRun.Shapes(Shapes(Circle(0, 0, 1), Circle(0, 0, 1), Circle(0, 0, 1), twoJoints)),
            "shapes[3].joints: must be an array of 3 numbers [φ1, φ2, φ3], got 2");
        CollideErrorTests.AssertOneLineFailure(
            CliRun.Collide(Pairs(Pair(zeroWidth, Circle(0, 0, 1)))),
            "pairs[0].a.size.width: must be > 0, got 0");
    }

    public static TheoryData<string, string> WrongJsonTypes() => new()
    {
        { """[{"type":"fish","position":[0,0],"heading":"x","joints":[0,0,0]}]""", "shapes[0].heading: expected a number at line 1, column 46" },
        { """[{"type":"fish","position":[0,0],"heading":0,"joints":{}}]""", "shapes[0].joints: expected an array of 3 numbers [φ1, φ2, φ3] at line 1, column 55" },
        { """[{"type":"fish","position":[0,0],"heading":0,"joints":[0,0,0],"size":5}]""", "shapes[0].size: expected an object {\"length\": L, \"width\": W, \"head\": H, \"joints\": [L1, L2, L3]} at line 1, column 70" },
        { """[{"type":"fish","position":[0,0],"heading":0,"joints":[0,0,0],"size":{"length":1,"width":1,"head":1,"joints":[1,true,1]}}]""", "shapes[0].size.joints[1]: expected a number at line 1, column 116" },
        { """[{"type":"fish","position":[0,"x"],"heading":0,"joints":[0,0,0]}]""", "shapes[0].position[1]: expected a number at line 1, column 33" },
    };

    [Theory]
    [MemberData(nameof(WrongJsonTypes))]
    public void AValueOfTheWrongJsonTypeIsReportedWithItsPosition(string json, string expected)
    {
        CollideErrorTests.AssertOneLineFailure(CliRun.Shapes(json), expected);
    }

    public static TheoryData<string, string> BadDocuments() => new()
    {
        { "", "shapes: input is empty" },
        { "null", "shapes: must be an array of SHAPE objects, got null" },
        { "{}", "shapes: expected an array of SHAPE objects at line 1, column 1" },
        { "[1]", "shapes[0]: expected a shape object {\"type\": ..., ...} at line 1, column 2" },
        { "[null]", "shapes[0]: must be a shape object {\"type\": ..., ...}, got null" },
        { """[{"type":"fish"}]""", "shapes[0].position: required field is missing or null" },
        { """[{"type":"fishy"}]""", "shapes[0].type: unknown shape type \"fishy\"" },
        { """[{"type":"circle","center":[0,0],"radius":-5}]""", "shapes[0].radius: must be > 0, got -5" },
        { "[" + Circle(0, 0, 1) + ",]", "shapes[1]: malformed JSON at line 1, column 46: The JSON array contains a trailing comma at the end which is not supported in this mode. Change the reader options." },
    };

    [Theory]
    [MemberData(nameof(BadDocuments))]
    public void ABadShapesDocumentIsReportedWithItsPath(string json, string expected)
    {
        CollideErrorTests.AssertOneLineFailure(CliRun.Shapes(json), expected);
    }

    [Fact]
    public void AnErrorAfterManyGoodFishWritesNothing()
    {
        var shapes = Enumerable.Range(0, 300).Select(i => Fish(i, -i, i * 0.01)).Append("""{"type":"fish","position":[0,0],"heading":0,"joints":[0,0,"NaN"]}""").ToArray();

        CollideErrorTests.AssertOneLineFailure(CliRun.Shapes(Shapes(shapes)), "shapes[300].joints[2]: must be a finite number, got NaN");
    }
}
