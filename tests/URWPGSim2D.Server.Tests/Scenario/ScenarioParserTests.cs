using URWPGSim2D.Engine.Matches;

namespace URWPGSim2D.Server.Tests.Scenario;

/// <summary>Scenario files: defaults, the embedded default match and one-line errors naming the JSON path.</summary>
public sealed class ScenarioParserTests
{
    [Fact]
    public void EverythingButFishAndBallsHasTheDocumentedDefaults()
    {
        var s = ScenarioFile.Parse("""{"fish":[{"team":1,"position":[10,20]}],"balls":[{"position":[0,0]}]}""");
        Assert.Equal((3000f, 2000f, true), (s.FieldLength, s.FieldWidth, s.GoalBlocks));
        Assert.Equal((3000, 1UL, true), (s.Cycles, s.Seed, s.Noise));
        Assert.Empty(s.Obstacles);
        var f = Assert.Single(s.Fish);
        Assert.Equal((1, 10f, 20f, 0f, "idle"), (f.Team, f.Position.X, f.Position.Y, f.Heading, f.Strategy));
        var b = Assert.Single(s.Balls);
        Assert.Equal((58f, 0f, 0f), (b.Radius, b.Velocity.X, b.Velocity.Y));
    }

    [Fact]
    public void TheIssueExampleParses()
    {
        var s = ScenarioFile.Parse("""
            { "field": {"length": 3000, "width": 2000, "goalBlocks": true},
              "cycles": 3000, "seed": 1, "noise": true,
              "fish": [ {"team": 0, "position": [-500, 0], "heading": 0.0, "strategy": "chase-ball"},
                        {"team": 1, "position": [500, 0], "heading": 3.14, "decision": {"vcode": 14, "tcode": 7}} ],
              "balls": [ {"position": [0, 0], "velocity": [10, -20], "radius": 58} ],
              "obstacles": [ {"type": "rectangle", "center": [0, 500], "length": 100, "width": 100, "heading": 0.0},
                             {"type": "round", "center": [0, -500], "radius": 58} ] }
            """);
        Assert.Equal("fixed", s.Fish[1].Strategy);
        Assert.Equal((14, 7), (s.Fish[1].Decision.VCode, s.Fish[1].Decision.TCode));
        Assert.Equal(ObstacleKind.Rectangle, s.Obstacles[0].Kind);
        Assert.Equal((ObstacleKind.Round, 58f), (s.Obstacles[1].Kind, s.Obstacles[1].Radius));
    }

    [Fact]
    public void TheDefaultMatchIsThePapersScene()
    {
        var s = DefaultScenario.Load();
        Assert.Equal((3000f, 2000f, true, 3000, 1UL), (s.FieldLength, s.FieldWidth, s.GoalBlocks, s.Cycles, s.Seed));
        Assert.Equal(2, s.Fish.Count(f => f.Team == 0));
        Assert.Equal(2, s.Fish.Count(f => f.Team == 1));
        Assert.All(s.Fish, f => Assert.Equal("chase-ball", f.Strategy));
        Assert.Equal(9, s.Balls.Count);
        Assert.Equal(2, s.Obstacles.Count(o => o.Kind == ObstacleKind.Rectangle));
        Assert.Equal(2, s.Obstacles.Count(o => o.Kind == ObstacleKind.Round));
        var match = MatchBuilder.Build(s);
        Assert.Equal(4 + 4, match.World.Statics.Length);
        Assert.Equal(0.0, OverlapAuditOf(match));
    }

    [Theory]
    [InlineData("""{"fish":[],"balls":[{"position":[0,0]},{"position":[300,0]},{"position":[0,300],"radius":-5}]}""", "balls[2].radius: must be > 0, got -5")]
    [InlineData("""{"balls":[]}""", "fish: is required")]
    [InlineData("""{"fish":[]}""", "balls: is required")]
    [InlineData("""{"fish":[],"balls":[],"colour":"red"}""", "colour: unknown property (expected one of: field, cycles, seed, noise, fish, balls, obstacles)")]
    [InlineData("""{"fish":[{"team":2,"position":[0,0]}],"balls":[]}""", "fish[0].team: must be 0..1, got 2")]
    [InlineData("""{"fish":[{"position":[0,0]}],"balls":[]}""", "fish[0].team: is required")]
    [InlineData("""{"fish":[{"team":0,"position":[0]}],"balls":[]}""", "fish[0].position: must be [x, z], got an array")]
    [InlineData("""{"fish":[{"team":0,"position":[0,"a"]}],"balls":[]}""", "fish[0].position[1]: must be a number, got the string \"a\"")]
    [InlineData("""{"fish":[{"team":0,"position":[1600,0]}],"balls":[]}""", "fish[0].position: must be inside the field (|x| < 1500, |z| < 1000), got [1600, 0]")]
    [InlineData("""{"fish":[{"team":0,"position":[0,0],"strategy":"dance"}],"balls":[]}""", "fish[0].strategy: must be \"idle\", \"chase-ball\" or \"fixed\", got \"dance\"")]
    [InlineData("""{"fish":[{"team":0,"position":[0,0],"strategy":"fixed"}],"balls":[]}""", "fish[0].decision: is required for strategy \"fixed\"")]
    [InlineData("""{"fish":[{"team":0,"position":[0,0],"decision":{"vcode":16,"tcode":7}}],"balls":[]}""", "fish[0].decision.vcode: must be 0..15, got 16")]
    [InlineData("""{"fish":[{"team":0,"position":[0,0],"strategy":"idle","decision":{"vcode":1,"tcode":7}}],"balls":[]}""", "fish[0].decision: is only for strategy \"fixed\", not \"idle\"")]
    [InlineData("""{"fish":[],"balls":[{"position":[1460,0]}]}""", "balls[0].position: the ball (radius 58) must lie inside the field, got [1460, 0]")]
    [InlineData("""{"fish":[],"balls":[],"obstacles":[{"type":"hexagon","center":[0,0]}]}""", "obstacles[0].type: must be \"rectangle\" or \"round\", got \"hexagon\"")]
    [InlineData("""{"fish":[],"balls":[],"obstacles":[{"type":"round","center":[0,0],"length":5}]}""", "obstacles[0].length: unknown property (expected one of: type, center, radius)")]
    [InlineData("""{"fish":[],"balls":[],"obstacles":[{"type":"rectangle","center":[0,0],"width":0}]}""", "obstacles[0].width: must be > 0, got 0")]
    [InlineData("""{"fish":[],"balls":[],"cycles":-1}""", "cycles: must be 0..2147483647, got -1")]
    [InlineData("""{"fish":[],"balls":[],"cycles":1.5}""", "cycles: must be an integer, got 1.5")]
    [InlineData("""{"fish":[],"balls":[],"noise":"yes"}""", "noise: must be true or false, got the string \"yes\"")]
    [InlineData("""{"fish":[],"balls":[],"field":{"length":100}}""", "field.length: must be >= 600 (room for a fish and both goals), got 100")]
    [InlineData("""{"fish":[],"balls":[],"field":{"width":"wide"}}""", "field.width: must be a number, got the string \"wide\"")]
    [InlineData("""[]""", "(root): must be an object, got an array")]
    [InlineData("""{"fish":[],""", "invalid JSON at line 1, column 11")]
    public void BadScenariosFailWithOneLineNamingThePath(string json, string message)
    {
        var e = Assert.Throws<ScenarioException>(() => ScenarioFile.Parse(json));
        Assert.Equal(message, e.Message);
        Assert.DoesNotContain('\n', e.Message);
    }

    private static double OverlapAuditOf(Match match) => Simulation.OverlapAudit.DeepestOverlap(match.World, out _);
}
