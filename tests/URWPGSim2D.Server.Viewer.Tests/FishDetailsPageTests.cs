using static URWPGSim2D.Server.Viewer.Tests.PageProbe;

namespace URWPGSim2D.Server.Viewer.Tests;

/// <summary>
/// A body's details and trajectories in the replay page: a fish or a ball clicked on the pool (or
/// chosen in the list) shows the numbers of the trace's line — position, heading, speeds, joints,
/// decision, gears, contacts, the team's faults — and the trajectories of the chosen bodies over a
/// chosen window are the trace's positions, drawn on the pool. The ball-grab demo's plan (its
/// drawings) shows where the trace has it.
/// </summary>
[Collection(BrowserCollection.Name)]
public sealed class FishDetailsPageTests(Browser browser, RecordedMatch match)
{
    // Packing steps of the page's data (positions 0.1 mm, angles 1e-4 rad): half a step, and a little for float32.
    private const double Mm = 0.051, Rad = 0.000051;

    private sealed record Details(string Id, int Cycle, int? Team, double[] Position, double? Heading, double[]? Joints, double? Speed, double? AngularSpeed,
        int[]? Decision, int[]? Gears, double[]? Velocity, Contact[] Contacts, Fault[]? Faults);

    private sealed record Contact(string Other, string? Part, string? OtherPart);

    private sealed record Fault(int Cycle, string Text);

    private (string Html, JsonElement[] Lines) Record(string name, params string[] args)
    {
        string html = Path.Combine(match.Folder, name + ".html"), trace = Path.Combine(match.Folder, name + ".jsonl");
        var run = RecordedMatch.Cli(["run", .. args, "--trace", trace, "--html", html]);
        Assert.True(run.Code == 0, run.Stderr);
        return (html, File.ReadLines(trace).Select(l => JsonDocument.Parse(l).RootElement.Clone()).ToArray());
    }

    private static async Task<Details> Shown(IPage page) =>
        JsonSerializer.Deserialize<Details>(await page.EvaluateAsync<string>("() => JSON.stringify(urwpg.details())"), new JsonSerializerOptions(JsonSerializerDefaults.Web))!;

    private static double[] Pair(JsonElement p) => [p[0].GetDouble(), p[1].GetDouble()];

    // The contacts of a body in a trace line, as the other body and the parts (own first).
    private static Contact[] ContactsOf(JsonElement line, string id) =>
        line.GetProperty("contacts").EnumerateArray()
            .Where(c => c.GetProperty("a").GetString() == id || c.GetProperty("b").GetString() == id)
            .Select(c => c.GetProperty("a").GetString() == id
                ? new Contact(c.GetProperty("b").GetString()!, c.GetProperty("partA").GetString(), c.GetProperty("partB").GetString())
                : new Contact(c.GetProperty("a").GetString()!, c.GetProperty("partB").GetString(), c.GetProperty("partA").GetString()))
            .ToArray();

    // The same JSON value: numbers by value (the page prints them its own way), the rest exactly.
    private static bool Same(JsonElement a, JsonElement b) => (a.ValueKind, b.ValueKind) switch
    {
        (JsonValueKind.Number, JsonValueKind.Number) => a.GetDouble() == b.GetDouble(),
        (JsonValueKind.Array, JsonValueKind.Array) => a.GetArrayLength() == b.GetArrayLength() && a.EnumerateArray().Zip(b.EnumerateArray()).All(p => Same(p.First, p.Second)),
        (JsonValueKind.Object, JsonValueKind.Object) => a.EnumerateObject().Count() == b.EnumerateObject().Count()
            && a.EnumerateObject().All(p => b.TryGetProperty(p.Name, out var q) && Same(p.Value, q)),
        var (x, y) when x == y => a.GetRawText() == b.GetRawText(),
        _ => false,
    };

    private static void Close(double expected, double actual, double tolerance, string what) =>
        Assert.True(Math.Abs(expected - actual) <= tolerance, $"{what}: the trace has {expected}, the page {actual}");

    [Fact]
    public async Task A_fish_or_ball_chosen_shows_the_traces_numbers_decision_gears_and_contacts()
    {
        var (html, lines) = Record("details", "--item", "ball-grab", "--cycles", "300", "--debug-draw");
        var (page, errors, requests) = await OpenFile(browser, html);
        var layout = lines[0].GetProperty("layout");
        int fishCount = layout.GetProperty("fish").GetArrayLength(), ballCount = layout.GetProperty("balls").GetArrayLength();
        int contactsSeen = 0;
        foreach (int cycle in (int[])[0, 1, 37, 150, 151, 299, 300])
        {
            await Scrub(page, cycle);
            var line = lines[cycle];

            // The ball-grab demo's plan: the page holds the shapes the trace has for this cycle.
            var shown = JsonDocument.Parse(await page.EvaluateAsync<string>("k => JSON.stringify(urwpg.drawingsAt(k))", cycle)).RootElement;
            Assert.True(Same(line.TryGetProperty("draw", out var draw) ? draw : JsonDocument.Parse("[]").RootElement, shown), $"cycle {cycle}: the page's drawings are not the trace's");
            Assert.True(cycle == 0 || shown.GetArrayLength() > 0, $"cycle {cycle}: no drawings");
            for (int i = 0; i < fishCount; i++)
            {
                await page.SelectOptionAsync("#inspect", "fish" + i);
                var d = await Shown(page);
                var f = line.GetProperty("fish")[i];
                string at = $"cycle {cycle} fish{i}";
                Assert.Equal(("fish" + i, cycle), (d.Id, d.Cycle));
                Assert.Equal(layout.GetProperty("fish")[i].GetProperty("team").GetInt32(), d.Team);
                Close(Pair(f.GetProperty("position"))[0], d.Position[0], Mm, at + " x");
                Close(Pair(f.GetProperty("position"))[1], d.Position[1], Mm, at + " z");
                double heading = f.GetProperty("heading").GetDouble();
                Close(0, Math.IEEERemainder(heading - d.Heading!.Value, 2 * Math.PI), Rad, at + " heading");
                for (int j = 0; j < 3; j++)
                {
                    Close(f.GetProperty("joints")[j].GetDouble(), d.Joints![j], Rad, at + " joint " + (j + 1));
                }

                Close(f.GetProperty("speed").GetDouble(), d.Speed!.Value, Mm, at + " speed");
                Close(f.GetProperty("angularSpeed").GetDouble(), d.AngularSpeed!.Value, Rad, at + " angular speed");
                if (cycle == 0)
                {
                    Assert.Null(d.Decision);
                    Assert.Null(d.Gears);
                }
                else
                {
                    Assert.Equal(f.GetProperty("decision").EnumerateArray().Select(v => v.GetInt32()), d.Decision!);
                    Assert.Equal(f.GetProperty("gears").EnumerateArray().Select(v => v.GetInt32()), d.Gears!);
                }

                Assert.Equal(ContactsOf(line, "fish" + i), d.Contacts);
                contactsSeen += d.Contacts.Length;
                Assert.Empty(d.Faults!);
            }

            for (int b = 0; b < ballCount; b++)
            {
                await page.SelectOptionAsync("#inspect", "ball" + b);
                var d = await Shown(page);
                var ball = line.GetProperty("balls")[b];
                for (int axis = 0; axis < 2; axis++)
                {
                    Close(Pair(ball.GetProperty("position"))[axis], d.Position[axis], Mm, $"cycle {cycle} ball{b} position");
                    Close(Pair(ball.GetProperty("velocity"))[axis], d.Velocity![axis], Mm, $"cycle {cycle} ball{b} velocity");
                }

                Assert.Equal(ContactsOf(line, "ball" + b), d.Contacts);
                contactsSeen += d.Contacts.Length;
            }
        }

        Assert.True(contactsSeen > 0, "some chosen cycle has contacts"); // else the contact check checked nothing

        // The panel shows the decision in words.
        await Scrub(page, 150);
        await page.SelectOptionAsync("#inspect", "fish1");
        var f1 = lines[150].GetProperty("fish")[1].GetProperty("decision");
        Assert.Equal($"VCode {f1[0].GetInt32()}, TCode {f1[1].GetInt32()}", await page.TextContentAsync("#details-body tr[data-name='decision'] td"));

        lock (requests)
        {
            Assert.Equal([new Uri(html).AbsoluteUri], requests.Where(u => !u.StartsWith("data:", StringComparison.Ordinal)).ToArray());
        }

        NoErrors(errors);
        await page.Context.CloseAsync();
    }

    [Fact]
    public async Task Clicking_a_fish_or_a_ball_on_the_pool_chooses_it()
    {
        var (page, errors, _) = await OpenFile(browser, match.HtmlPath);
        await Scrub(page, 400);
        var line = match.Lines[400];
        for (int i = 0; i < 4; i++)
        {
            await ClickWorld(page, Point(line.GetProperty("fish")[i].GetProperty("position")));
            Assert.Equal("fish" + i, await page.InputValueAsync("#inspect"));
            Assert.Equal("fish" + i, (await Shown(page)).Id);
        }

        // A ball not covered by a fish: its centre is outside every fish's leaves.
        var fish = Enumerable.Range(0, 4).Select(i => Point(line.GetProperty("fish")[i].GetProperty("position"))).ToArray();
        int free = Enumerable.Range(0, 9).First(b =>
        {
            var c = Point(line.GetProperty("balls")[b].GetProperty("position"));
            return fish.All(m => Vector2.Distance(m, c) > 250f);
        });
        await ClickWorld(page, Point(line.GetProperty("balls")[free].GetProperty("position")));
        Assert.Equal("ball" + free, await page.InputValueAsync("#inspect"));
        NoErrors(errors);
        await page.Context.CloseAsync();
    }

    private static async Task ClickWorld(IPage page, Vector2 world)
    {
        var css = await page.EvaluateAsync<double[]>("p => { const q = urwpg.worldToCanvas(p[0], p[1]); return [q[0] / urwpg.view.dpr, q[1] / urwpg.view.dpr]; }", new double[] { world.X, world.Y });
        Assert.True(double.IsFinite(css[0]) && double.IsFinite(css[1]), $"{world} is at ({css[0]}, {css[1]}) on the canvas");
        await page.Locator("#pool").ClickAsync(new() { Position = new() { X = (float)css[0], Y = (float)css[1] } });
        await Settle(page);
    }

    [Fact]
    public async Task Trajectories_of_chosen_bodies_over_a_window_are_the_traces_positions_drawn_on_the_pool()
    {
        var (page, errors, _) = await OpenFile(browser, match.HtmlPath);
        await page.ClickAsync("#show-labels");
        await Scrub(page, 900);
        await page.SelectOptionAsync("#inspect", "fish2");
        await page.CheckAsync("#track-body");
        await page.SelectOptionAsync("#inspect", "ball4");
        await page.CheckAsync("#track-body");
        await page.FillAsync("#trajectory-from", "300");
        await page.FillAsync("#trajectory-to", "600");
        await page.Locator("#trajectory-to").DispatchEventAsync("change");
        await Settle(page);
        Assert.Equal(["fish2", "ball4"], await page.EvaluateAsync<string[]>("() => urwpg.tracked"));

        foreach (var (id, get) in new (string, Func<JsonElement, JsonElement>)[] { ("fish2", l => l.GetProperty("fish")[2]), ("ball4", l => l.GetProperty("balls")[4]) })
        {
            var shown = await page.EvaluateAsync<double[][]>("id => urwpg.trajectory(id)", id);
            Assert.Equal(301, shown.Length);
            for (int k = 0; k < shown.Length; k++)
            {
                var p = Pair(get(match.Lines[300 + k]).GetProperty("position"));
                Close(p[0], shown[k][0], Mm, $"{id} at cycle {300 + k} x");
                Close(p[1], shown[k][1], Mm, $"{id} at cycle {300 + k} z");
            }
        }

        // Fish 2's line is drawn in its team's colour: most of its points show it (a fish or ball of cycle 900 may cover a few).
        var fish2 = Enumerable.Range(300, 301).Where(c => c % 10 == 0).Select(c => Point(match.Lines[c].GetProperty("fish")[2].GetProperty("position"))).ToArray();
        var rgb = await Pixels(page, fish2);
        int team = match.Layout.GetProperty("fish")[2].GetProperty("team").GetInt32();
        int coloured = rgb.Count(c => Near(c, Team[team]));
        Assert.True(coloured >= fish2.Length * 3 / 5, $"{coloured} of {fish2.Length} points of fish2's trajectory show its colour");

        // Untracked: gone.
        await page.SelectOptionAsync("#inspect", "fish2");
        await page.UncheckAsync("#track-body");
        await Settle(page);
        int left = (await Pixels(page, fish2)).Count(c => Near(c, Team[team]));
        Assert.True(left < coloured / 3, $"{left} of {fish2.Length} points still show fish2's colour once it is not tracked"); // only where a fish of the team lies now
        Assert.Equal(["ball4"], await page.EvaluateAsync<string[]>("() => urwpg.tracked"));
        NoErrors(errors);
        await page.Context.CloseAsync();
    }

    [Fact]
    public async Task A_fish_shows_its_teams_faults_up_to_the_cycle_shown()
    {
        string thrower = SdkStrategy.Write(match.Folder, "Thrower", "thrower", """
            if (s.Cycle == 20 || s.Cycle == 40) throw new InvalidOperationException("cycle " + s.Cycle);
            for (int i = 0; i < d.Length; i++) d[i] = new Decision(8, 7);
            """);
        var (html, lines) = Record("faults", "--item", "default", "--cycles", "60", "--strategy", "0=" + thrower, "--isolation", "none");
        var faults = lines.SelectMany(l => l.GetProperty("events").EnumerateArray().Where(e => e.GetProperty("kind").GetString() == "fault")
            .Select(e => new Fault(l.GetProperty("cycle").GetInt32(), e.GetProperty("text").GetString()!))).ToArray();
        Assert.Equal(2, faults.Length);
        var (page, errors, _) = await OpenFile(browser, html);
        await page.SelectOptionAsync("#inspect", "fish0");
        foreach (int cycle in (int[])[10, faults[0].Cycle, 50])
        {
            await Scrub(page, cycle);
            Assert.Equal(faults.Where(f => f.Cycle <= cycle), (await Shown(page)).Faults!);
        }

        Assert.StartsWith("2, last #" + faults[1].Cycle + ": ", await page.TextContentAsync("#details-body tr[data-name='team faults'] td"), StringComparison.Ordinal);
        await page.SelectOptionAsync("#inspect", "fish2"); // team 1 (chase-ball): none
        Assert.Empty((await Shown(page)).Faults!);
        NoErrors(errors);
        await page.Context.CloseAsync();
    }

    [Fact]
    public async Task Fish_are_labelled_by_their_number_in_their_team_from_1_as_students_code_numbers_them()
    {
        // Ball-grab: fish0 and fish1 are team 0's Fishes[0] and Fishes[1] (its fish 1 and 2), fish2 and fish3 team 1's.
        var (html, _) = Record("labels", "--item", "ball-grab", "--cycles", "20");
        var (page, errors, _) = await OpenFile(browser, html);
        Assert.Equal(["T0\u00b71", "T0\u00b72", "T1\u00b71", "T1\u00b72"], await page.EvaluateAsync<string[]>("() => [0, 1, 2, 3].map(i => urwpg.fishLabel(i))"));
        Assert.Equal(
            ["fish0 (team 0 \u00b7 1)", "fish1 (team 0 \u00b7 2)", "fish2 (team 1 \u00b7 1)", "fish3 (team 1 \u00b7 2)"],
            await page.EvaluateAsync<string[]>("() => Array.from(document.querySelectorAll('#inspect option')).slice(1, 5).map(o => o.textContent)"));
        Assert.Equal("fish2 (team 1 \u00b7 1)", await page.EvaluateAsync<string>("() => document.querySelector('#follow option[value=\"2\"]').textContent"));
        NoErrors(errors);
        await page.Context.CloseAsync();
    }

    [Fact]
    public async Task A_link_to_a_cycle_opens_the_replay_page_at_that_cycle()
    {
        // The tournament report links a team's first fault as replays/match-J.html#cycle=N.
        var (html, _) = Record("at-cycle", "--item", "ball-grab", "--cycles", "60");
        var (page, errors, _) = await OpenFile(browser, html, "#cycle=40");
        Assert.Equal(40, await Cycle(page));
        Assert.Equal("cycle 40 / 60", await page.TextContentAsync("#cycle"));
        Assert.False(await page.EvaluateAsync<bool>("() => urwpg.playing"));
        NoErrors(errors);
        await page.Context.CloseAsync();
    }

    [Fact]
    public async Task ScreenshotOfTheDetailsAndTrajectories()
    {
        var (html, _) = Record("details-figure", "--item", "ball-grab", "--cycles", "600", "--debug-draw");
        var (page, errors, _) = await OpenFile(browser, html);
        await Scrub(page, 450);
        foreach (string id in (string[])["ball2", "fish0"])
        {
            await page.SelectOptionAsync("#inspect", id);
            await page.CheckAsync("#track-body");
        }

        await page.FillAsync("#trajectory-from", "300");
        await page.Locator("#trajectory-from").DispatchEventAsync("change");
        await Settle(page);
        Assert.Equal("cycle 450 / 600", await page.TextContentAsync("#cycle"));
        await Figures.Shoot(page, "fish-details.png", match.Folder);
        NoErrors(errors);
        await page.Context.CloseAsync();
    }
}
