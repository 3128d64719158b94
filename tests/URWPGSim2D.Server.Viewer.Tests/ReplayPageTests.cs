using System.Globalization;
using URWPGSim2D.Collision.Fish;
using Xunit.Sdk;
using static URWPGSim2D.Server.Viewer.Tests.PageProbe;

namespace URWPGSim2D.Server.Viewer.Tests;

/// <summary>The replay page of <c>run --html</c> / <c>view</c> in headless Chromium, checked against the trace.</summary>
[Collection(BrowserCollection.Name)]
public sealed class ReplayPageTests(Browser browser, RecordedMatch match)
{
    // Opens a replay page (the recorded match's by default) with every request but the page itself aborted and recorded.
    private Task<(IPage Page, List<string> Errors, List<string> Requests)> Open(string? path = null) => OpenFile(browser, path ?? match.HtmlPath);

    private static async Task Labels(IPage page, bool on)
    {
        if (await page.IsCheckedAsync("#show-labels") != on)
        {
            await page.ClickAsync("#show-labels");
        }

        await Settle(page);
    }

    [Fact]
    public void ThePageIsSelfContainedSmallAndTheSameFromRunAndView()
    {
        long size = new FileInfo(match.HtmlPath).Length;
        Assert.True(size <= 5_000_000, $"6,000 cycles, 4 fish, 9 balls: {size:N0} bytes > 5 MB");
        string html = File.ReadAllText(match.HtmlPath);
        Assert.DoesNotContain("http://", html, StringComparison.Ordinal);
        Assert.DoesNotContain("https://", html, StringComparison.Ordinal);
        Assert.DoesNotContain(" src=", html, StringComparison.Ordinal);
        Assert.DoesNotContain("<link rel=\"stylesheet\"", html, StringComparison.Ordinal);
        Assert.Equal(6001, match.Lines.Length);
        Assert.Equal(File.ReadAllBytes(match.HtmlPath), File.ReadAllBytes(match.ViewHtmlPath));
        Assert.Equal($"{match.ViewHtmlPath}: 6001 cycles\n", match.ViewStdout.Replace("\r\n", "\n", StringComparison.Ordinal));
    }

    [Fact]
    public async Task FirstFrameWithinTwoSecondsWithoutAnyNetworkRequest()
    {
        var (page, errors, requests) = await Open();
        double firstFrame = await page.EvaluateAsync<double>("() => urwpg.firstFrameAt");
        Assert.True(firstFrame < 2000, $"first frame after {firstFrame:0} ms");
        await Settle(page);
        lock (requests)
        {
            Assert.Equal([new Uri(match.HtmlPath).AbsoluteUri], requests.Where(u => !u.StartsWith("data:", StringComparison.Ordinal)).ToArray());
        }

        NoErrors(errors);
        await page.Context.CloseAsync();
    }

    [Fact]
    public async Task EveryFishAndBallHasItsColourAtItsTracePosition()
    {
        var (page, errors, _) = await Open();
        await Labels(page, false);
        var layout = match.Layout;
        int checkedPoints = 0, skipped = 0;
        foreach (int cycle in (int[])[0, 1, 2, 3, 700, 1500, 3001, 4444, 6000])
        {
            await Scrub(page, cycle);
            Assert.Equal(cycle, await Cycle(page));
            var line = match.Lines[cycle];
            var fish = Fish(line, layout);
            var balls = line.GetProperty("balls").EnumerateArray().Select(b => Point(b.GetProperty("position"))).ToArray();
            var radii = layout.GetProperty("balls").EnumerateArray().Select(b => b.GetProperty("radius").GetSingle()).ToArray();
            var points = new List<(Vector2 At, (int, int, int) Colour, string What, int Fish, int Ball)>();
            for (int i = 0; i < fish.Length; i++)
            {
                int team = layout.GetProperty("fish")[i].GetProperty("team").GetInt32();
                points.Add((fish[i].Pose.Position, Team[team], $"fish{i} body", i, -1));
                points.Add((Centroid(fish[i].GetLeaf(FishPart.Tail1)), Team[team], $"fish{i} tail1", i, -1));
                points.Add((Centroid(fish[i].GetLeaf(FishPart.RightCaudal)), Team[team], $"fish{i} right caudal", i, -1));
            }

            for (int i = 0; i < balls.Length; i++)
            {
                points.Add((balls[i], Ball, $"ball{i}", -1, i));
            }

            float scale = await page.EvaluateAsync<float>("() => urwpg.view.scale");
            float margin = 3 / scale; // 3 px in mm
            var clear = points.Where(p => Clear(p.At, p.Fish, p.Ball, fish, balls, radii, margin)).ToList();
            skipped += points.Count - clear.Count;
            var rgb = await Pixels(page, clear.Select(p => p.At).ToArray());
            for (int i = 0; i < clear.Count; i++)
            {
                Assert.True(Near(rgb[i], clear[i].Colour), $"cycle {cycle}: {clear[i].What} at ({clear[i].At.X}, {clear[i].At.Y}) is {rgb[i]}, expected {clear[i].Colour}");
                checkedPoints++;
            }
        }

        Assert.True(checkedPoints >= 9 * 21 * 8 / 10, $"only {checkedPoints} points were clear of other bodies ({skipped} overlapped)");
        NoErrors(errors);
        await page.Context.CloseAsync();
    }

    // A sample point counts only when it lies well inside its own body and away from every other body.
    private static bool Clear(Vector2 p, int ownFish, int ownBall, FishModel[] fish, Vector2[] balls, float[] radii, float margin)
    {
        for (int i = 0; i < fish.Length; i++)
        {
            for (var part = FishPart.LeftPectoral; part <= FishPart.RightCaudal; part++)
            {
                float d = Inside(fish[i].GetLeaf(part), p);
                if (i == ownFish ? d > 0 && d < margin : d > -margin)
                {
                    if (i != ownFish || d < margin)
                    {
                        return false;
                    }
                }
            }
        }

        for (int i = 0; i < balls.Length; i++)
        {
            float d = Vector2.Distance(p, balls[i]);
            if (i == ownBall ? d > radii[i] - margin : d < radii[i] + margin)
            {
                return false;
            }
        }

        return true;
    }

    [Fact]
    public async Task TheLeavesOfThePageAreTheLibrarysAtAnyPoseAndSize()
    {
        var (page, errors, _) = await Open();
        var random = new Random(20261201);
        var sizes = new[] { FishSize.Default, new FishSize(200, 50, 40, 100, 70, 60), new FishSize(120, 30, 20, 60, 50, 40) };
        for (int n = 0; n < 300; n++)
        {
            try
            {
                var size = sizes[n % sizes.Length];
                var pose = new FishPose(new Vector2((float)((random.NextDouble() * 3000) - 1500), (float)((random.NextDouble() * 2000) - 1000)),
                    (float)((random.NextDouble() * 2 * Math.PI) - Math.PI), (float)((random.NextDouble() * 2.4) - 1.2), (float)((random.NextDouble() * 2.4) - 1.2), (float)((random.NextDouble() * 2.4) - 1.2));
                var model = new FishModel(size, pose);
                var js = await page.EvaluateAsync<double[][][]>(
                    "a => urwpg.leaves({ length: a[0], width: a[1], head: a[2], joints: [a[3], a[4], a[5]] }, a[6], a[7], a[8], a[9], a[10], a[11])",
                    new double[] { size.Length, size.Width, size.Head, size.Joint1, size.Joint2, size.Joint3, pose.Position.X, pose.Position.Y, pose.Heading, pose.Joint1, pose.Joint2, pose.Joint3 });
                Assert.Equal(8, js.Length);
                for (var part = FishPart.LeftPectoral; part <= FishPart.RightCaudal; part++)
                {
                    var leaf = model.GetLeaf(part).ToArray();
                    var mine = js[(int)part];
                    Assert.True(leaf.Length == mine.Length, $"pose {n}: {part} has {mine.Length} vertices, the library {leaf.Length}");
                    foreach (var v in mine)
                    {
                        float best = leaf.Min(q => Vector2.Distance(q, new Vector2((float)v[0], (float)v[1])));
                        Assert.True(best < 2e-3f, $"pose {n} ({pose}, {size}): {part} vertex ({v[0]}, {v[1]}) is {best} mm from the library's");
                    }
                }
            }
            catch (XunitException e)
            {
                throw RandomCaseException.At(20261201, n, e);
            }
        }

        NoErrors(errors);
        await page.Context.CloseAsync();
    }

    [Fact]
    public async Task ClockAndScoreFollowTheScrubBar()
    {
        var (page, errors, _) = await Open();
        var goals = match.Events;
        Assert.True(goals.Count >= 2, "the two thrown balls score");
        int firstGoal = goals[0].Cycle;
        foreach (int cycle in (int[])[0, firstGoal - 1, firstGoal, 1234, 5999, 6000])
        {
            await Scrub(page, cycle);
            var score = match.Lines[cycle].GetProperty("score");
            string expectedScore = $"{score[0].GetDouble().ToString(CultureInfo.InvariantCulture)} : {score[1].GetDouble().ToString(CultureInfo.InvariantCulture)}";
            int seconds = cycle / 10;
            Assert.Equal($"{seconds / 60:00}:{seconds % 60:00}", await page.TextContentAsync("#clock"));
            Assert.Equal($"cycle {cycle} / 6000", await page.TextContentAsync("#cycle"));
            Assert.Equal(expectedScore, await page.TextContentAsync("#score"));
        }

        // The score before and at the first goal differ: the scrub bar moved it.
        await Scrub(page, firstGoal - 1);
        string before = (await page.TextContentAsync("#score"))!;
        await Scrub(page, firstGoal);
        Assert.NotEqual(before, await page.TextContentAsync("#score"));
        NoErrors(errors);
        await page.Context.CloseAsync();
    }

    [Fact]
    public async Task PlayAdvancesAndPauseHolds()
    {
        var (page, errors, _) = await Open();
        await Scrub(page, 100);
        await page.SelectOptionAsync("#speed", "16");
        await page.ClickAsync("#play");
        await page.WaitForFunctionAsync("() => urwpg.cycle >= 130", null, new() { Timeout = Browser.HangMs });
        await page.ClickAsync("#play");
        int held = await Cycle(page);
        Assert.False(await page.EvaluateAsync<bool>("() => urwpg.playing"));
        await Settle(page);
        await Settle(page);
        Assert.Equal(held, await Cycle(page));
        Assert.Equal($"cycle {held} / 6000", await page.TextContentAsync("#cycle"));

        // Keyboard: space plays and pauses, + and − change the speed.
        await page.ClickAsync("#pool");
        await page.Keyboard.PressAsync("Space");
        await page.WaitForFunctionAsync($"() => urwpg.cycle > {held}", null, new() { Timeout = Browser.HangMs });
        await page.Keyboard.PressAsync("Space");
        Assert.False(await page.EvaluateAsync<bool>("() => urwpg.playing"));
        await page.Keyboard.PressAsync("-");
        Assert.Equal("8", await page.InputValueAsync("#speed"));
        await page.Keyboard.PressAsync("+");
        await page.Keyboard.PressAsync("+");
        Assert.Equal("16", await page.InputValueAsync("#speed"));
        for (int i = 0; i < 8; i++)
        {
            await page.Keyboard.PressAsync("-");
        }

        Assert.Equal("0.25", await page.InputValueAsync("#speed"));
        NoErrors(errors);
        await page.Context.CloseAsync();
    }

    [Fact]
    public async Task StepAndJumpToEventLandOnTheRightCycle()
    {
        var (page, errors, _) = await Open();
        await Scrub(page, 100);
        await page.ClickAsync("#pool");
        await page.Keyboard.PressAsync("ArrowRight");
        Assert.Equal(101, await Cycle(page));
        await page.ClickAsync("#fwd");
        Assert.Equal(102, await Cycle(page));
        await page.Keyboard.PressAsync("ArrowLeft");
        await page.ClickAsync("#back");
        Assert.Equal(100, await Cycle(page));
        await page.Keyboard.PressAsync("Shift+ArrowRight");
        Assert.Equal(110, await Cycle(page));

        // Jump to the next event, from the start, as the trace has them.
        await Scrub(page, 0);
        var cycles = match.Events.Select(e => e.Cycle).Distinct().ToList();
        int at = 0;
        for (int jump = 0; jump < Math.Min(4, cycles.Count + 1); jump++)
        {
            int expected = cycles.FirstOrDefault(c => c > at, at);
            await page.ClickAsync("#next");
            await Settle(page);
            Assert.Equal(expected, await Cycle(page));
            if (expected != at)
            {
                string text = match.Events.Last(e => e.Cycle == expected).Text;
                Assert.Contains(text, await page.TextContentAsync("#events li:first-child"), StringComparison.Ordinal);
            }

            at = expected;
        }

        await page.Keyboard.PressAsync("Home");
        Assert.Equal(0, await Cycle(page));
        await page.Keyboard.PressAsync("n");
        Assert.Equal(cycles[0], await Cycle(page));
        NoErrors(errors);
        await page.Context.CloseAsync();
    }

    [Fact]
    public async Task ContactsFollowAndOverlaysDraw()
    {
        var (page, errors, _) = await Open();
        await Labels(page, false);

        // A cycle with exactly one contact: its action point is drawn yellow, its normal black.
        int cycle = Array.FindIndex(match.Lines, l => l.GetProperty("contacts").GetArrayLength() == 1 && l.GetProperty("cycle").GetInt32() > 50);
        Assert.True(cycle > 0, "the match has a cycle with one contact");
        var contact = match.Lines[cycle].GetProperty("contacts")[0];
        var point = Point(contact.GetProperty("actionPoint"));
        var normal = Point(contact.GetProperty("normal"));
        await Scrub(page, cycle);
        await page.ClickAsync("#show-contacts");
        await Settle(page);
        var rgb = await Pixels(page, [point, point + (normal * 40)]);
        Assert.True(Near(rgb[0], (0xff, 0xf2, 0x00)), $"cycle {cycle}: action point ({point.X}, {point.Y}) is {rgb[0]}, not yellow");
        Assert.True(rgb[1].R < 90 && rgb[1].G < 90 && rgb[1].B < 90, $"cycle {cycle}: the normal 40 mm from the action point is {rgb[1]}, not black");
        await page.ClickAsync("#show-contacts");

        // Bounds and trails add drawing; following a fish centres and zooms on it.
        string plain = await page.EvaluateAsync<string>("() => document.getElementById('pool').toDataURL()");
        await page.ClickAsync("#show-bounds");
        await Settle(page);
        Assert.NotEqual(plain, await page.EvaluateAsync<string>("() => document.getElementById('pool').toDataURL()"));
        await page.ClickAsync("#show-bounds");
        await page.ClickAsync("#show-trails");
        await Settle(page);
        Assert.NotEqual(plain, await page.EvaluateAsync<string>("() => document.getElementById('pool').toDataURL()"));
        await page.ClickAsync("#show-trails");
        await page.SelectOptionAsync("#follow", "2");
        await Settle(page);
        var p = Point(match.Lines[cycle].GetProperty("fish")[2].GetProperty("position"));
        var centre = await page.EvaluateAsync<double[]>("() => [document.getElementById('pool').width / 2, document.getElementById('pool').height / 2]");
        var mapped = await page.EvaluateAsync<double[]>("a => urwpg.worldToCanvas(a[0], a[1])", new double[] { p.X, p.Y });
        Assert.Equal(centre[0], mapped[0], 0.5);
        Assert.Equal(centre[1], mapped[1], 0.5);
        var atCentre = await Pixels(page, [p]);
        Assert.True(Near(atCentre[0], Team[1]), $"the followed fish 2 (team 1) is not at the centre: {atCentre[0]}");
        NoErrors(errors);
        await page.Context.CloseAsync();
    }

    [Fact]
    public async Task AOneTeamItemShowsItsOneTeamAndItsScoreAlone()
    {
        // Transport: one team of two fish. The trace lists two teams and two scores (its contract's
        // shape) but team 1 has no fish; the page shows team 0 and its score only.
        string html = Path.Combine(match.Folder, "transport.html"), trace = Path.Combine(match.Folder, "transport.jsonl");
        var run = RecordedMatch.Cli("run", "--item", "transport", "--cycles", "30", "--html", html, "--trace", trace);
        Assert.True(run.Code == 0, run.Stderr);
        using (var first = JsonDocument.Parse(File.ReadLines(trace).First()))
        {
            var layout = first.RootElement.GetProperty("layout");
            Assert.Equal(2, layout.GetProperty("teams").GetArrayLength());
            Assert.All(layout.GetProperty("fish").EnumerateArray(), f => Assert.Equal(0, f.GetProperty("team").GetInt32()));
        }

        var (page, errors, _) = await Open(html);
        await Settle(page);
        Assert.True(await page.IsVisibleAsync("#team0"));
        Assert.False(await page.IsVisibleAsync("#team1"));
        Assert.Equal("0", await page.TextContentAsync("#score"));
        NoErrors(errors);
        await page.Context.CloseAsync();
    }

    [Fact]
    public async Task AFourTeamMatchReplaysWithItsFourTeamsColoursAndScores()
    {
        // 4支队伍测试: four teams of three fish; the trace lists four teams and four scores.
        string html = Path.Combine(match.Folder, "four-teams.html"), trace = Path.Combine(match.Folder, "four-teams.jsonl");
        var run = RecordedMatch.Cli("run", "--item", "four-teams", "--cycles", "40", "--html", html, "--trace", trace);
        Assert.True(run.Code == 0, run.Stderr);
        var lines = File.ReadLines(trace).Select(l => JsonDocument.Parse(l).RootElement).ToArray();
        var layout = lines[0].GetProperty("layout");
        Assert.Equal(4, layout.GetProperty("teams").GetArrayLength());
        Assert.Equal(41, lines.Length);
        Assert.All(lines, l => Assert.Equal(4, l.GetProperty("score").GetArrayLength()));

        var (page, errors, _) = await Open(html);
        await Labels(page, false);
        for (int t = 0; t < 4; t++)
        {
            Assert.True(await page.IsVisibleAsync("#team" + t));
            Assert.Equal("team " + t + " (four-teams demo)", await page.TextContentAsync("#team" + t + " .name"));
        }

        Assert.Equal("0 : 0 : 0 : 0", await page.TextContentAsync("#score"));

        // Every fish's body in its team's colour, at the start and at the end of the replay.
        foreach (int cycle in (int[])[0, 40])
        {
            await Scrub(page, cycle);
            Assert.Equal(cycle, await Cycle(page));
            var fish = Fish(lines[cycle], layout);
            var rgb = await Pixels(page, fish.Select(f => f.Pose.Position).ToArray());
            for (int i = 0; i < fish.Length; i++)
            {
                int team = layout.GetProperty("fish")[i].GetProperty("team").GetInt32();
                Assert.True(Near(rgb[i], Team[team]), $"cycle {cycle}: fish{i} of team {team} is {rgb[i]}, expected {Team[team]}");
            }
        }

        NoErrors(errors);
        await page.Context.CloseAsync();
    }

    [Fact]
    public async Task ScreenshotForTheReadme()
    {
        // The README's picture: the page of the README's command (the default match), at cycle 1000.
        // The match is deterministic, so its first 1000 cycles are those of the full match.
        string html = Path.Combine(match.Folder, "default.html");
        var run = RecordedMatch.Cli("run", "--cycles", "1000", "--html", html);
        Assert.True(run.Code == 0, run.Stderr);
        var (page, errors, _) = await Open(html);
        await page.ClickAsync("#show-trails");
        await page.Keyboard.PressAsync("End");
        await Settle(page);
        Assert.Equal("cycle 1000 / 1000", await page.TextContentAsync("#cycle"));
        await Figures.Shoot(page, "match.png", match.Folder);
        NoErrors(errors);
        await page.Context.CloseAsync();
    }
}
