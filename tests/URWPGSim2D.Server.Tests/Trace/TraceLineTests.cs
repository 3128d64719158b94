using URWPGSim2D.Engine.Trace;

namespace URWPGSim2D.Server.Tests.Trace;

/// <summary>The trace additions of docs/viewer.md: item, layout, score and events.</summary>
public sealed class TraceLineTests
{
    private const string DefaultLikeScenario =
        "{\"fish\":[{\"team\":0,\"position\":[-1000,-400],\"heading\":0,\"strategy\":\"idle\"},{\"team\":1,\"position\":[1000,400],\"heading\":3.1415927,\"strategy\":\"idle\"}]," +
        "\"balls\":[{\"position\":[0,0]},{\"position\":[1200,0],\"velocity\":[2000,0]},{\"position\":[-1200,0],\"velocity\":[-2000,0]}]," +
        "\"obstacles\":[{\"type\":\"rectangle\",\"center\":[-600,-650],\"length\":100,\"width\":60,\"heading\":0.5},{\"type\":\"round\",\"center\":[600,-650],\"radius\":58}]}";

    private static JsonElement Line(TraceLine lines, ReadOnlySpan<ContactRecord> contacts) =>
        JsonDocument.Parse(Encoding.UTF8.GetString(lines.Write(contacts))).RootElement.Clone();

    [Fact]
    public void Cycle0LineCarriesTheLayoutOfTheWorld()
    {
        var match = TestMatches.FromJson(DefaultLikeScenario);
        var line = Line(new TraceLine(match.World, match.Teams, match.Rules), ReadOnlySpan<ContactRecord>.Empty);
        Assert.Equal(0, line.GetProperty("cycle").GetInt32());
        Assert.Equal("default", line.GetProperty("item").GetString());
        var layout = line.GetProperty("layout");
        Assert.Equal(3000, layout.GetProperty("field").GetProperty("length").GetDouble());
        Assert.Equal(2000, layout.GetProperty("field").GetProperty("width").GetDouble());

        // Goal mouths: |z| <= 200, 150 deep at each end; team 0 attacks +X so it defends the left goal.
        var goals = layout.GetProperty("goals");
        Assert.Equal(2, goals.GetArrayLength());
        Assert.Equal("{\"team\":0,\"min\":[-1500,-200],\"max\":[-1350,200]}", goals[0].GetRawText());
        Assert.Equal("{\"team\":1,\"min\":[1350,-200],\"max\":[1500,200]}", goals[1].GetRawText());
        Assert.Equal(0, World.ScoringTeam(-1) == 1 ? 0 : 1); // the ball in the left goal scores for team 1: team 0 defends it

        var blocks = layout.GetProperty("goalBlocks");
        Assert.Equal(4, blocks.GetArrayLength());
        Assert.Equal("{\"min\":[-1500,-1000],\"max\":[-1350,-200]}", blocks[0].GetRawText());
        Assert.Equal("{\"min\":[1350,200],\"max\":[1500,1000]}", blocks[3].GetRawText());

        var obstacles = layout.GetProperty("obstacles");
        Assert.Equal("{\"type\":\"rectangle\",\"center\":[-600,-650],\"length\":100,\"width\":60,\"heading\":0.5}", obstacles[0].GetRawText());
        Assert.Equal("{\"type\":\"round\",\"center\":[600,-650],\"radius\":58}", obstacles[1].GetRawText());
        Assert.Equal(0, layout.GetProperty("zones").GetArrayLength());
        Assert.Equal("[{\"id\":0,\"name\":\"idle\"},{\"id\":1,\"name\":\"idle\"}]", layout.GetProperty("teams").GetRawText());
        Assert.Equal(
            "[{\"team\":0,\"index\":0,\"size\":{\"length\":160,\"width\":45,\"head\":30,\"joints\":[88,66,55]}},{\"team\":1,\"index\":0,\"size\":{\"length\":160,\"width\":45,\"head\":30,\"joints\":[88,66,55]}}]",
            layout.GetProperty("fish").GetRawText());
        Assert.Equal("[{\"radius\":58},{\"radius\":58},{\"radius\":58}]", layout.GetProperty("balls").GetRawText());
        Assert.Equal("[0,0]", line.GetProperty("score").GetRawText());
        Assert.Equal("[]", line.GetProperty("events").GetRawText());
    }

    [Fact]
    public void LaterLinesHaveScoreAndEventsButNoLayout()
    {
        var match = TestMatches.FromJson(DefaultLikeScenario);
        var lines = new TraceLine(match.World, match.Teams, match.Rules);
        _ = lines.Write(ReadOnlySpan<ContactRecord>.Empty);
        var goalCycles = new List<(int Cycle, int Team, int Ball)>();
        var score = new double[2];
        for (int k = 1; k <= 30; k++)
        {
            match.Step();
            var line = Line(lines, match.Contacts.Cycle);
            Assert.Equal(k, line.GetProperty("cycle").GetInt32());
            Assert.False(line.TryGetProperty("layout", out _), $"cycle {k} has a layout");
            Assert.False(line.TryGetProperty("item", out _), $"cycle {k} has an item");
            foreach (var e in line.GetProperty("events").EnumerateArray())
            {
                Assert.Equal("goal", e.GetProperty("kind").GetString());
                int team = e.GetProperty("team").GetInt32(), ball = e.GetProperty("ball").GetInt32();
                Assert.Equal($"team {team} scores ball {ball}", e.GetProperty("text").GetString());
                score[team] += e.GetProperty("value").GetDouble();
                goalCycles.Add((k, team, ball));
            }

            // The score is the running sum of the goal events (an invariant, not the same code path).
            Assert.Equal($"[{score[0]},{score[1]}]", line.GetProperty("score").GetRawText());
        }

        // Ball 1 runs into the right goal (team 0 scores), ball 2 into the left one (team 1 scores).
        Assert.Contains(goalCycles, g => g.Team == 0 && g.Ball == 1);
        Assert.Contains(goalCycles, g => g.Team == 1 && g.Ball == 2);
        var goalEvents = match.Rules.Events;
        Assert.Equal(goalEvents.Count, goalCycles.Count);
        for (int i = 0; i < goalEvents.Count; i++)
        {
            Assert.Equal((goalEvents[i].Cycle, goalEvents[i].Team, goalEvents[i].Ball), goalCycles[i]);
        }
    }

    [Fact]
    public void AnItemSuppliesSlugZonesValuesScoreAndEvents()
    {
        var match = TestMatches.FromJson(DefaultLikeScenario);
        var item = new StubItem();
        var lines = new TraceLine(match.World, match.Teams, item);
        var line0 = Line(lines, ReadOnlySpan<ContactRecord>.Empty);
        Assert.Equal("ball-grab", line0.GetProperty("item").GetString());
        Assert.Equal(
            "[{\"kind\":\"hole\",\"id\":0,\"center\":[100,-200],\"radius\":75},{\"kind\":\"target\",\"id\":1,\"team\":1,\"min\":[-10,-20],\"max\":[30,40]},{\"kind\":\"forbidden\",\"id\":2,\"polygon\":[[0,0],[100,0],[0,50.5]]}]",
            line0.GetProperty("layout").GetProperty("zones").GetRawText());
        Assert.Equal("[{\"radius\":58,\"value\":3},{\"radius\":58},{\"radius\":58,\"value\":0.5}]", line0.GetProperty("layout").GetProperty("balls").GetRawText());
        Assert.Equal("[0,0.5]", line0.GetProperty("score").GetRawText());
        match.Step();
        var line1 = Line(lines, match.Contacts.Cycle);
        Assert.Equal("[1,1.5]", line1.GetProperty("score").GetRawText());
        Assert.Equal("[{\"kind\":\"catch\",\"team\":1,\"fish\":1,\"ball\":2,\"value\":2.5,\"text\":\"fish 1 catches ball 2\"},{\"kind\":\"end\",\"text\":\"cycle 1\"}]", line1.GetProperty("events").GetRawText());
    }

    private sealed class StubItem : ITraceItemInfo
    {
        public string Slug => "ball-grab";

        public IReadOnlyList<TraceZone> Zones { get; } =
        [
            TraceZone.Circle("hole", 0, new Vector2(100, -200), 75),
            TraceZone.Box("target", 1, new Vector2(-10, -20), new Vector2(30, 40), team: 1),
            TraceZone.Polygon("forbidden", 2, [new(0, 0), new(100, 0), new(0, 50.5f)]),
        ];

        private int _cycle;

        public double? BallValue(int ball) => ball switch { 0 => 3, 2 => 0.5, _ => null };

        public double Score(int team) => _cycle + (team * 0.5);

        public void AddEvents(int cycle, List<TraceEvent> events)
        {
            _cycle = cycle;
            events.Add(new TraceEvent("catch", "fish 1 catches ball 2", Team: 1, Fish: 1, Ball: 2, Value: 2.5));
            events.Add(new TraceEvent("end", $"cycle {cycle}"));
        }
    }
}
