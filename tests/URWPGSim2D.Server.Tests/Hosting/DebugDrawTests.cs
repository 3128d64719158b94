using URWPGSim2D.Engine.Items.BallGrab;
using OriginalDraw = URWPGSim2D.StrategyHelper.DebugDraw;

namespace URWPGSim2D.Server.Tests.Hosting;

/// <summary>
/// Strategy debug drawings (<c>run --debug-draw</c>): the shapes a strategy draws reach the trace where
/// it put them — in the server's process and from a strategy host, in both APIs — and drawing costs
/// nothing when they are not recorded (no allocation, the same trace bytes).
/// </summary>
[Collection(InProcessStaticsCollection.Name)]
public sealed class DebugDrawTests() : TempFolderTest("urwpg-draw-")
{
    // An SDK strategy that circles each of its fish (per fish, team colour), joins it to ball 0 (per fish, green) and marks ball 0 for the team.
    private string SdkDrawer() => SdkStrategy.Write(Folder, "SdkDrawer", "sdk drawer", """
        for (int i = 0; i < d.Length; i++)
        {
            var me = s.Fish[fish[i]];
            d[i] = new Decision(6, 5);
            DebugDraw.Circle(me.Position, 50f, fish[i], 0xffd700);
            if (s.Balls.Length > 0)
            {
                DebugDraw.Line(me.Position, s.Balls[0].Position, fish[i]);
            }
        }

        if (s.Balls.Length > 0 && DebugDraw.IsOn)
        {
            DebugDraw.Text(s.Balls[0].Position, "ball 0");
        }
        """);

    private static JsonElement[] Lines(string trace) => File.ReadLines(trace).Select(l => JsonDocument.Parse(l).RootElement.Clone()).ToArray();

    private static Vector2 Point(JsonElement p) => new(p[0].GetSingle(), p[1].GetSingle());

    [Fact]
    public void Drawings_land_in_the_trace_where_the_strategy_put_them_in_process_and_from_a_host_in_both_apis()
    {
        string[] specs = [SdkDrawer(), OriginalStrategyTests.Folder("Drawer")];
        for (int api = 0; api < specs.Length; api++)
        {
            string spec = specs[api];
            var traces = new List<byte[]>();
            foreach (string isolation in new[] { "none", "process" })
            {
                string trace = Path.Combine(Folder, $"{api}-{isolation}.jsonl");
                var run = CliRun.Of(string.Empty, "run", "--item", "default", "--noise", "off", "--cycles", "30", "--strategy", "0=" + spec,
                    "--isolation", isolation, "--strategy-timeout", "5000", "--debug-draw", "--trace", trace);
                Assert.True(run.ExitCode == 0, run.Stderr);
                Assert.Contains("strategy faults: none", run.Stdout, StringComparison.Ordinal);
                var lines = Lines(trace);
                Assert.False(lines[0].TryGetProperty("draw", out _), "cycle 0 has no decisions, so no drawings");
                var layout = lines[0].GetProperty("layout").GetProperty("fish");
                int[] team0 = Enumerable.Range(0, layout.GetArrayLength()).Where(i => layout[i].GetProperty("team").GetInt32() == 0).ToArray();
                for (int n = 1; n < lines.Length; n++)
                {
                    // Drawn from the snapshot of the previous line (noise off: exactly its positions), written with the cycle the decisions drive.
                    var seen = lines[n - 1];
                    var mine = lines[n].GetProperty("draw").EnumerateArray().Where(d => d.GetProperty("team").GetInt32() == 0).ToArray();
                    Assert.Equal((2 * team0.Length) + 1, mine.Length);
                    var ball = Point(seen.GetProperty("balls")[0].GetProperty("position"));
                    foreach (int f in team0)
                    {
                        var at = Point(seen.GetProperty("fish")[f].GetProperty("position"));
                        var circle = Assert.Single(mine, d => d.GetProperty("kind").GetString() == "circle" && d.GetProperty("fish").GetInt32() == f);
                        Assert.Equal(at, Point(circle.GetProperty("center")));
                        Assert.Equal(50f, circle.GetProperty("radius").GetSingle());
                        Assert.Equal("#ffd700", circle.GetProperty("color").GetString());
                        var line = Assert.Single(mine, d => d.GetProperty("kind").GetString() == "line" && d.GetProperty("fish").GetInt32() == f);
                        Assert.Equal(at, Point(line.GetProperty("from")));
                        Assert.Equal(ball, Point(line.GetProperty("to")));
                        Assert.False(line.TryGetProperty("color", out _), "the team's colour is left out");
                    }

                    var text = Assert.Single(mine, d => d.GetProperty("kind").GetString() == "text");
                    Assert.Equal("ball 0", text.GetProperty("text").GetString());
                    Assert.Equal(ball, Point(text.GetProperty("at")));
                    Assert.False(text.TryGetProperty("fish", out _), "a team drawing has no fish");
                }

                traces.Add(File.ReadAllBytes(trace));
            }

            Assert.True(traces[0].AsSpan().SequenceEqual(traces[1]), $"{Path.GetFileName(spec)}: a hosted strategy's drawings differ from the same strategy's in process");
        }
    }

    [Theory]
    [InlineData("default")] // chase-ball draws its plan every cycle
    [InlineData("ball-grab")] // the demo draws its plan every cycle it is not escaping a wall
    public void Without_debug_draw_the_trace_is_the_same_bytes_as_with_it_less_the_drawings(string item)
    {
        string on = Path.Combine(Folder, "on.jsonl"), off = Path.Combine(Folder, "off.jsonl");
        var a = CliRun.Of(string.Empty, "run", "--item", item, "--cycles", "200", "--debug-draw", "--trace", on);
        var b = CliRun.Of(string.Empty, "run", "--item", item, "--cycles", "200", "--trace", off);
        Assert.True(a.ExitCode == 0 && b.ExitCode == 0, a.Stderr + b.Stderr);
        var stripped = new StringBuilder();
        int drawn = 0;
        foreach (string line in File.ReadLines(on))
        {
            int at = line.IndexOf(",\"draw\":[", StringComparison.Ordinal);
            drawn += at >= 0 ? 1 : 0;
            stripped.Append(at >= 0 ? line[..at] + "}" : line).Append('\n');
        }

        Assert.Equal(200, drawn);
        string offText = File.ReadAllText(off);
        Assert.DoesNotContain("\"draw\"", offText, StringComparison.Ordinal);
        Assert.Equal(offText, stripped.ToString());
    }

    [Fact]
    public void Drawing_calls_allocate_nothing_when_drawings_are_not_recorded()
    {
        var xna = new Microsoft.Xna.Framework.Vector3(1f, 0f, 2f);
        for (int warm = 0; warm < 2; warm++)
        {
            long before = GC.GetAllocatedBytesForCurrentThread();
            for (int i = 0; i < 1000; i++)
            {
                Strategies.DebugDraw.Point(new Vector2(i, 1f), 0, 0xff0000);
                Strategies.DebugDraw.Line(Vector2.Zero, new Vector2(i, 1f));
                Strategies.DebugDraw.Circle(Vector2.One, i);
                Strategies.DebugDraw.Text(Vector2.One, "text", 1);
                OriginalDraw.Point(xna, 0, System.Drawing.Color.Red);
                OriginalDraw.Line(xna, xna);
                OriginalDraw.Circle(xna, i);
                OriginalDraw.Text(xna, "text", 1);
            }

            long allocated = GC.GetAllocatedBytesForCurrentThread() - before;
            Assert.False(Strategies.DebugDraw.IsOn || OriginalDraw.IsOn);
            if (warm == 1)
            {
                Assert.Equal(0L, allocated); // the first round also pays for compiling the calls
            }
        }
    }

    [Fact]
    public void The_default_match_with_its_drawing_demo_strategy_allocates_nothing_per_cycle_without_debug_draw()
    {
        var match = MatchBuilder.Build(DefaultScenario.Load());
        Assert.All(match.Caller().Slots, s => Assert.Null(s.Drawings));
        match.Play(300);
        long before = GC.GetAllocatedBytesForCurrentThread();
        match.Play(300);
        Assert.Equal(0L, GC.GetAllocatedBytesForCurrentThread() - before);
    }

    [Fact]
    public void The_ball_grab_demo_draws_each_fishs_ball_its_route_into_the_teams_box_and_what_it_is_doing()
    {
        string trace = Path.Combine(Folder, "ball-grab.jsonl");
        var run = CliRun.Of(string.Empty, "run", "--item", "ball-grab", "--noise", "off", "--cycles", "300", "--debug-draw", "--trace", trace);
        Assert.True(run.ExitCode == 0, run.Stderr);
        var lines = Lines(trace);
        var layout = lines[0].GetProperty("layout");
        int plans = 0;
        var boxSide = new Dictionary<int, int>();
        for (int n = 1; n < lines.Length; n++)
        {
            var seen = lines[n - 1];
            var balls = seen.GetProperty("balls").EnumerateArray().Select(b => Point(b.GetProperty("position"))).ToArray();
            foreach (var text in lines[n].GetProperty("draw").EnumerateArray().Where(d => d.GetProperty("kind").GetString() == "text"))
            {
                int fish = text.GetProperty("fish").GetInt32();
                int team = text.GetProperty("team").GetInt32();
                Assert.Equal(team, layout.GetProperty("fish")[fish].GetProperty("team").GetInt32());
                string what = text.GetProperty("text").GetString()!;
                if (!what.StartsWith("push ball ", StringComparison.Ordinal) && !what.StartsWith("fetch ball ", StringComparison.Ordinal))
                {
                    Assert.Contains(what, new[] { "leave box", "wait" });
                    continue;
                }

                // The circled ball is the one named, where the demo's filter has it (noise off: within 40 mm of where it was).
                int ball = int.Parse(what[(what.LastIndexOf(' ') + 1)..], System.Globalization.CultureInfo.InvariantCulture);
                var mine = lines[n].GetProperty("draw").EnumerateArray().Where(d => d.TryGetProperty("fish", out var f) && f.GetInt32() == fish).ToArray();
                var circle = Assert.Single(mine, d => d.GetProperty("kind").GetString() == "circle");
                Assert.True(Vector2.Distance(Point(circle.GetProperty("center")), balls[ball]) < 40f, $"cycle {n}: the circle is not on ball {ball}");

                // The route (green) is a chain of segments from the circled ball into one of the boxes, the same box for a team.
                var route = mine.Where(d => d.GetProperty("kind").GetString() == "line" && d.TryGetProperty("color", out var c) && c.GetString() == "#2e8b57").ToArray();
                Assert.NotEmpty(route);
                Assert.Equal(Point(circle.GetProperty("center")), Point(route[0].GetProperty("from")));
                for (int i = 1; i < route.Length; i++)
                {
                    Assert.Equal(Point(route[i - 1].GetProperty("to")), Point(route[i].GetProperty("from")));
                }

                var end = Point(route[^1].GetProperty("to"));
                int side = Math.Sign(end.X);
                Assert.True(Math.Abs(end.X) > BallGrabLayout.BoxInnerX && Math.Abs(end.X) < BallGrabLayout.BoxOuterX && Math.Abs(end.Y) < BallGrabLayout.BoxHalfWidth, $"cycle {n}: the route of team {team} ends at {end}, not in a box");
                if (boxSide.TryGetValue(team, out int was) && was != side)
                {
                    // The teams change ends at half time (the 300-cycle match's half is 150 cycles).
                    Assert.Equal(151, n);
                }

                boxSide[team] = side;
                plans++;
            }
        }

        Assert.True(plans > 400, $"only {plans} plans drawn in 300 cycles of 4 fish");
        Assert.Equal(-boxSide[0], boxSide[1]); // the two teams' boxes are at opposite ends (and each team's stay put but for the half)
    }

    [Fact]
    public void A_recorder_keeps_at_most_its_bounds_per_cycle()
    {
        var recorder = new Strategies.DebugRecorder();
        recorder.Enter([3, 5]);
        try
        {
            for (int i = 0; i < 200; i++)
            {
                Strategies.DebugDraw.Point(new Vector2(i, 0f), i % 2 == 0 ? 5 : 4);
            }
        }
        finally
        {
            Strategies.DebugRecorder.Exit();
        }

        Assert.Equal(Strategies.DebugRecorder.MaxShapes, recorder.Count);
        Assert.Equal(200 - Strategies.DebugRecorder.MaxShapes, recorder.Dropped);
        Assert.All(recorder.Shapes.ToArray(), s => Assert.Equal(s.A.X % 2 == 0 ? 5 : -1, s.Fish)); // fish 4 is not the strategy's: the team's
        Assert.False(Strategies.DebugDraw.IsOn);

        recorder.Enter([0]);
        Strategies.DebugDraw.Text(Vector2.Zero, new string('a', 3000));
        Strategies.DebugDraw.Text(Vector2.Zero, new string('b', 3000));
        Strategies.DebugDraw.Text(Vector2.Zero, "c");
        Strategies.DebugDraw.Line(new Vector2(float.NaN, 0f), Vector2.One);
        Strategies.DebugRecorder.Exit();
        Assert.Equal(2, recorder.Count);
        Assert.Equal(Strategies.DebugRecorder.MaxTextChars, recorder.Shapes[0].Text!.Length + recorder.Shapes[1].Text!.Length);
        Assert.Equal(2, recorder.Dropped); // the text past the bound and the line that is not finite
    }

    [Fact]
    public void Debug_draw_without_a_recording_is_a_usage_error()
    {
        var run = CliRun.Of(string.Empty, "run", "--cycles", "10", "--debug-draw");
        Assert.Equal(2, run.ExitCode);
        Assert.Contains("--debug-draw records the strategies' drawings in --trace, --html or --live; give one of them", run.Stderr, StringComparison.Ordinal);
        Assert.DoesNotContain(" at ", run.Stderr, StringComparison.Ordinal);
    }
}
