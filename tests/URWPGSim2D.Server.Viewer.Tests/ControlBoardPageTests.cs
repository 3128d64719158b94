using System.Threading;
using URWPGSim2D.Hosting;
using URWPGSim2D.Engine.Scenario;
using static URWPGSim2D.Server.Viewer.Tests.PageProbe;

namespace URWPGSim2D.Server.Viewer.Tests;

/// <summary>
/// The live page's control board (<c>run --live --strategies DIR</c>) in Chromium: it starts the
/// chosen item with the chosen strategies of DIR (the match the server streams says so), the match
/// pauses, steps exactly one cycle and restarts; recompile plays an edited source; a strategy that
/// does not compile is shown in the board with the command line's lines and the page plays on; the
/// replay page and the PNG are saved without any request beyond the server. Every check waits for a
/// state (bounded), never for an amount of time.
/// </summary>
[Collection(BrowserCollection.Name)]
public sealed class ControlBoardPageTests(Browser browser) : IDisposable
{
    private const int Wait = Browser.HangMs;
    private readonly string _folder = Path.Combine(Path.GetTempPath(), "urwpg-board-page-" + Guid.NewGuid().ToString("N"));

    public void Dispose() => Directory.Delete(_folder, recursive: true);

    private sealed record Live(string Url, CancellationTokenSource Stop, Task<int> Served, StringWriter Error);

    // A strategy that calls itself name and swims ahead, turning a little.
    private static string Named(string name, string extra = "") => $$"""
        using System;
        using URWPGSim2D.Strategies;
        namespace BoardTeam
        {
            public sealed class Named : IStrategy
            {
                public string TeamName => "{{name}}";
                public void Decide(MatchSnapshot snapshot, ReadOnlySpan<int> fish, Span<Decision> decisions)
                {
                    {{extra}}
                    for (int i = 0; i < decisions.Length; i++) decisions[i] = new Decision(12, 8);
                }
            }
        }
        """;

    private void Write(string name, string source)
    {
        string file = Path.Combine(_folder, name);
        Directory.CreateDirectory(Path.GetDirectoryName(file)!);
        File.WriteAllText(file, source);
    }

    private async Task<Live> Start()
    {
        int port = LiveViewTests.FreePort();
        var options = RunOptions.Parse(["--live", "--paused", "--item", "default", "--strategy-timeout", "5000", "--port", port.ToString(System.Globalization.CultureInfo.InvariantCulture), "--strategies", _folder]);
        var url = new TaskCompletionSource<string>(TaskCreationOptions.RunContinuationsAsynchronously);
        var stop = new CancellationTokenSource();
        var error = new StringWriter();
        var console = new CliConsole(new StringReader(string.Empty), TextWriter.Synchronized(new StringWriter()), TextWriter.Synchronized(error));
        var served = Task.Run(() => LiveRun.Serve(options, DefaultScenario.Load(), new TeamStrategy?[4], console, stop.Token, u => url.TrySetResult(u)));
        Assert.True(await Task.WhenAny(url.Task, served, Task.Delay(Wait)) == url.Task, "the live server did not start");
        return new Live(await url.Task, stop, served, error);
    }

    private static async Task Stop(Live live)
    {
        live.Stop.Cancel();
        Assert.True(await Task.WhenAny(live.Served, Task.Delay(Wait)) == live.Served, "the server did not stop");
        Assert.Equal(0, await live.Served);
    }

    private async Task<(IPage Page, List<string> Errors, List<string> Requests)> Open(Live live)
    {
        var (page, errors) = await browser.NewPageAsync();
        var requests = new List<string>();
        page.Request += (_, r) =>
        {
            lock (requests)
            {
                requests.Add(r.Url);
            }
        };
        await page.GotoAsync(live.Url);
        await page.WaitForFunctionAsync("() => window.urwpg && urwpg.serverStatus && urwpg.board && urwpg.boardLoads === 1", null, new() { Timeout = Wait });
        return (page, errors, requests);
    }

    private static Task PausedAt(IPage page, int cycle) =>
        page.WaitForFunctionAsync(
            "c => urwpg.store && urwpg.serverStatus && urwpg.serverStatus.paused && urwpg.serverStatus.cycle === c && urwpg.store.count === c + 1", cycle, new() { Timeout = Wait });

    private static Task<string[]> TeamNames(IPage page) => page.EvaluateAsync<string[]>("() => urwpg.store.layout.teams.map(t => t.name)");

    // Clicks a board button and waits for the server's answer to be shown.
    private static async Task Press(IPage page, string button)
    {
        int before = await page.EvaluateAsync<int>("() => urwpg.boardReplies");
        await page.ClickAsync(button);
        await page.WaitForFunctionAsync("n => urwpg.boardReplies === n + 1", before, new() { Timeout = Wait });
    }

    private static void OnlyTheServer(Live live, List<string> requests)
    {
        lock (requests)
        {
            Assert.NotEmpty(requests);
            Assert.All(requests, u => Assert.True(u.StartsWith(live.Url, StringComparison.Ordinal) || u.StartsWith("data:", StringComparison.Ordinal), "a request beyond the server: " + u));
        }
    }

    [Fact]
    public async Task The_board_starts_the_chosen_item_with_the_chosen_strategies_which_pause_step_restart_and_save()
    {
        Write("orcas/Strategy.cs", Named("orcas"));
        Write("sharks.cs", Named("sharks"));
        var live = await Start();
        var (page, errors, requests) = await Open(live);
        Assert.Equal(["scene", "idle", "chase-ball", "orcas/", "sharks.cs"], await page.EvalOnSelectorAllAsync<string[]>("#board-team0 option", "o => o.map(x => x.value)"));

        // Choose: polo 1v1, one minute, orcas against sharks; start plays it.
        await page.SelectOptionAsync("#board-item", "polo-1v1");
        Assert.Equal(["scene", "demo", "idle", "chase-ball", "orcas/", "sharks.cs"], await page.EvalOnSelectorAllAsync<string[]>("#board-team0 option", "o => o.map(x => x.value)"));
        await page.SelectOptionAsync("#board-length", "m1");
        await page.SelectOptionAsync("#board-team0", "orcas/");
        await page.SelectOptionAsync("#board-team1", "sharks.cs");
        await Press(page, "#board-start");
        Assert.False(await page.EvaluateAsync<bool>("() => urwpg.boardMessage.bad"), await page.TextContentAsync("#board-message"));
        await page.WaitForFunctionAsync("() => urwpg.store && urwpg.store.item === 'polo-1v1' && urwpg.serverStatus.cycles === 600 && !urwpg.serverStatus.paused", null, new() { Timeout = Wait });
        Assert.Equal(["orcas", "sharks [sharks.cs]"], await TeamNames(page));
        Assert.Equal("team 0 (orcas)", await page.TextContentAsync("#team0 .name"));

        // Pause holds; a step plays exactly one cycle.
        await page.ClickAsync("#server-pause");
        await page.WaitForFunctionAsync("() => urwpg.serverStatus.paused && urwpg.store.count === urwpg.serverStatus.cycle + 1", null, new() { Timeout = Wait });
        int held = await page.EvaluateAsync<int>("() => urwpg.serverStatus.cycle");
        await PausedAt(page, held);
        await page.ClickAsync("#server-step");
        await PausedAt(page, held + 1);
        await page.ClickAsync("#server-step");
        await PausedAt(page, held + 2);
        await Settle(page);
        await Figures.Shoot(page, "control-board.png", _folder);

        // The replay page of what was played, and the PNG of the field, saved by the browser.
        var replay = await page.RunAndWaitForDownloadAsync(() => page.ClickAsync("#board-save-replay"));
        Assert.Equal($"match-cycle{held + 2}.html", replay.SuggestedFilename);
        string saved = Path.Combine(_folder, "saved.html");
        await replay.SaveAsAsync(saved);
        string html = File.ReadAllText(saved);
        Assert.StartsWith("<!DOCTYPE html>", html, StringComparison.Ordinal);
        Assert.Contains($"\"item\":\"polo-1v1\",", html, StringComparison.Ordinal);
        Assert.Contains($",\"firstCycle\":0,\"cycles\":{held + 3},", html, StringComparison.Ordinal);
        var png = await page.RunAndWaitForDownloadAsync(() => page.ClickAsync("#board-save-png"));
        Assert.Equal($"field-cycle{held + 2}.png", png.SuggestedFilename);
        string picture = Path.Combine(_folder, "field.png");
        await png.SaveAsAsync(picture);
        byte[] bytes = File.ReadAllBytes(picture);
        Assert.Equal(new byte[] { 0x89, (byte)'P', (byte)'N', (byte)'G', 0x0d, 0x0a, 0x1a, 0x0a }, bytes[..8]);
        Assert.True(bytes.Length > 5_000, "the PNG has the field");

        // Restart: the same choice from cycle 0, paused as it was.
        await page.ClickAsync("#server-restart");
        await PausedAt(page, 0);
        Assert.Equal("polo-1v1", await page.EvaluateAsync<string>("() => urwpg.store.item"));
        Assert.Equal(["orcas", "sharks [sharks.cs]"], await TeamNames(page));

        // Recompile after an edit: the restarted match plays the new source.
        Write("orcas/Strategy.cs", Named("orcas-2"));
        await Press(page, "#board-recompile");
        Assert.StartsWith("compiling ", await page.TextContentAsync("#board-message"), StringComparison.Ordinal);
        await page.WaitForFunctionAsync("() => urwpg.store && urwpg.store.layout.teams[0].name === 'orcas-2 [orcas]' && urwpg.store.item === 'polo-1v1'", null, new() { Timeout = Wait });
        await PausedAt(page, 0);

        NoErrors(errors);
        OnlyTheServer(live, requests);
        await page.Context.CloseAsync();
        await Stop(live);
    }

    [Fact]
    public async Task A_strategy_that_does_not_compile_is_shown_in_the_board_and_the_page_plays_on()
    {
        Write("broken/Strategy.cs", Named("broken", "MessageBox.Show(\"hi\");"));
        var live = await Start();
        var (page, errors, requests) = await Open(live);
        await PausedAt(page, 0);
        await page.SelectOptionAsync("#board-team0", "broken/");
        await Press(page, "#board-start");

        // The lines run --strategy prints, the likely cause first after the file.
        var cli = RecordedMatch.Cli("run", "--item", "default", "--cycles", "1", "--strategy", "0=" + Path.Combine(_folder, "broken"));
        Assert.Equal(2, cli.Code);
        string[] expected = cli.Stderr.Split('\n').Where(l => l.Length > 0 && !l.StartsWith("compil", StringComparison.Ordinal)).ToArray();
        Assert.Contains("likely cause: MessageBox is a Windows or user-interface API", expected[0], StringComparison.Ordinal);
        Assert.True(await page.EvaluateAsync<bool>("() => urwpg.boardMessage.bad"));
        string[] shown = (await page.TextContentAsync("#board-message"))!.Split('\n').Where(l => l.Length > 0).ToArray();
        Assert.Equal([expected[0].Replace("--strategy 0: ", "team 0 (broken/): ", StringComparison.Ordinal), .. expected[1..]], shown);

        // The match it refused to replace plays on: a step plays one cycle of the default scene.
        await page.ClickAsync("#server-step");
        await PausedAt(page, 1);
        Assert.Equal("default", await page.EvaluateAsync<string>("() => urwpg.store.item"));

        // A bad length is refused by the server too, in the board.
        await page.SelectOptionAsync("#board-team0", "scene");
        await page.SelectOptionAsync("#board-length", "cycles");
        await page.FillAsync("#board-cycles", "-5");
        await Press(page, "#board-start");
        Assert.Equal("start: cycles must be an integer 0..2147483647, got \"-5\"\n", await page.TextContentAsync("#board-message"));

        // The only console errors are the browser's notes of the two refusals (400).
        Assert.Equal(2, errors.RemoveAll(e => e.Contains("the server responded with a status of 400", StringComparison.Ordinal)));
        NoErrors(errors);
        OnlyTheServer(live, requests);
        await page.Context.CloseAsync();
        await Stop(live);
    }
}
