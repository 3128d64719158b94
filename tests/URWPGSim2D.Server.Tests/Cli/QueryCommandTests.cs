using URWPGSim2D.Collision.Queries;

namespace URWPGSim2D.Server.Tests.Cli;

/// <summary>
/// <c>query</c>: one JSON line per query with the library's answers, in the documented fields;
/// bad input is one stderr line naming the place, exit code 2, nothing on stdout.
/// </summary>
public sealed class QueryCommandTests
{
    private const string Shapes = """
        "shapes":[{"type":"circle","center":[0,0],"radius":10},
                  {"type":"aabb","min":[30,-10],"max":[50,10]},
                  {"type":"fish","position":[600,0],"heading":0,"joints":[0,0,0]}]
        """;

    [Fact]
    public void EveryQueryKindAnswersWithTheLibrarysValues()
    {
        var run = CliRun.Of("{" + Shapes + """
            ,"queries":[{"type":"distance","a":0,"b":1},
                        {"type":"ray","from":[-100,5],"to":[100,5]},
                        {"type":"cast","shape":0,"translation":[100,0],"against":1},
                        {"type":"overlap","aabb":{"min":[-5,-5],"max":[35,5]}},
                        {"type":"distance","a":1,"b":2}]}
            """, "query", "-");
        Assert.Equal(0, run.ExitCode);
        Assert.Equal(string.Empty, run.Stderr);
        var lines = run.Stdout.Split('\n');
        Assert.Equal(6, lines.Length);
        Assert.Equal(string.Empty, lines[5]);

        Shape circle = new Circle(Vector2.Zero, 10f), box = new Aabb(new Vector2(30f, -10f), new Vector2(50f, 10f));
        var d = ShapeQuery.Distance(circle, box);
        using (var j = JsonDocument.Parse(lines[0]))
        {
            Assert.Equal(["distance", "pointA", "pointB"], j.RootElement.EnumerateObject().Select(p => p.Name));
            Assert.Equal(d.Distance, j.RootElement.GetProperty("distance").GetSingle());
        }

        var ray = ShapeQuery.RayCast(circle, new Vector2(-100f, 5f), new Vector2(100f, 5f));
        using (var j = JsonDocument.Parse(lines[1]))
        {
            Assert.Equal(["hit", "shape", "point", "normal", "fraction"], j.RootElement.EnumerateObject().Select(p => p.Name));
            Assert.Equal(0, j.RootElement.GetProperty("shape").GetInt32());
            Assert.Equal(ray.Fraction, j.RootElement.GetProperty("fraction").GetSingle());
        }

        var cast = ShapeQuery.Cast(circle, new Vector2(100f, 0f), box);
        using (var j = JsonDocument.Parse(lines[2]))
        {
            Assert.Equal(["hit", "fraction", "point", "normal"], j.RootElement.EnumerateObject().Select(p => p.Name));
            Assert.Equal(cast.Fraction, j.RootElement.GetProperty("fraction").GetSingle());
        }

        Assert.Equal("""{"shapes":[0,1]}""", lines[3]);
        Assert.Matches("\"partA\":null,\"partB\":\"(tail3|leftCaudal|rightCaudal)\"}$", lines[4]);
    }

    [Fact]
    public void AMissIsNullFields()
    {
        var run = CliRun.Of("{" + Shapes + ""","queries":[{"type":"ray","from":[0,500],"to":[10,500]},{"type":"cast","shape":0,"translation":[0,50],"against":1}]}""", "query", "-");
        Assert.Equal(
            """
            {"hit":false,"shape":null,"point":null,"normal":null,"fraction":null}
            {"hit":false,"fraction":null,"point":null,"normal":null}

            """.ReplaceLineEndings("\n"),
            run.Stdout);
    }

    public static TheoryData<string, string> BadInputs() => new()
    {
        { "", "input: input is empty" },
        { "[]", "input: expected an object {\"shapes\": [SHAPE, ...], \"queries\": [QUERY, ...]} at line 1, column 1" },
        { """{"queries":[]}""", "shapes: required field is missing or null" },
        { """{"shapes":[]}""", "queries: required field is missing or null" },
        { """{"shapes":[{"type":"circle","center":[0,0],"radius":-1}],"queries":[]}""", "shapes[0].radius: must be > 0, got -1" },
        { """{"shapes":[],"queries":[null]}""", "queries[0]: required field is missing or null" },
        { """{"shapes":[],"queries":[{"type":"warp"}]}""", "queries[0].type: unknown query type \"warp\" (distance, ray, cast or overlap)" },
        { """{"shapes":[],"queries":[{"type":"distance","a":0,"b":0}]}""", "queries[0].a: must be a shape index, but there are no shapes; got 0" },
        { """{"shapes":[{"type":"circle","center":[0,0],"radius":1}],"queries":[{"type":"distance","a":0,"b":3}]}""", "queries[0].b: must be a shape index 0 … 0, got 3" },
        { """{"shapes":[{"type":"circle","center":[0,0],"radius":1}],"queries":[{"type":"distance","a":0}]}""", "queries[0].b: required field is missing or null" },
        { """{"shapes":[],"queries":[{"type":"distance","a":1.5,"b":0}]}""", "queries[0].a: expected a shape index (an integer) at line 1, column 50" },
        { """{"shapes":[],"queries":[{"type":"ray","from":[0,"x"],"to":[1,1]}]}""", "queries[0].from[1]: expected a number at line 1, column 51" },
        { """{"shapes":[],"queries":[{"type":"ray","from":[0,0,0],"to":[1,1]}]}""", "queries[0].from: must be an array of 2 numbers [x, z], got 3" },
        { """{"shapes":[],"queries":[{"type":"ray","from":[0,"NaN"],"to":[1,1]}]}""", "queries[0].from: must have finite coordinates, got [0, NaN]" },
        { """{"shapes":[{"type":"circle","center":[0,0],"radius":1}],"queries":[{"type":"cast","shape":0,"against":0}]}""", "queries[0].translation: required field is missing or null" },
        { """{"shapes":[],"queries":[{"type":"overlap"}]}""", "queries[0].aabb: required field is missing or null" },
        { """{"shapes":[],"queries":[{"type":"overlap","aabb":{"min":[5,0],"max":[1,1]}}]}""", "queries[0].aabb.min: min x (5) is greater than max x (1)" },
    };

    [Theory]
    [MemberData(nameof(BadInputs))]
    public void BadInputIsOneLineAndExitCodeTwo(string json, string expected)
    {
        var run = CliRun.Of(json, "query", "-");
        Assert.Equal(2, run.ExitCode);
        Assert.Equal(string.Empty, run.Stdout);
        Assert.Equal(expected + "\n", run.Stderr.ReplaceLineEndings("\n"));
    }

    [Fact]
    public void HelpShowsTheQueryForms()
    {
        var run = CliRun.Of(string.Empty, "query", "--help");
        Assert.Equal(0, run.ExitCode);
        Assert.Contains("{\"type\":\"cast\",\"shape\":i,\"translation\":[x,z],\"against\":j}", run.Stdout);
        Assert.Contains("{\"type\":\"fish\"", run.Stdout);
    }
}
