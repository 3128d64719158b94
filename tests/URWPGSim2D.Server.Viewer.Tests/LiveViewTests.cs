using System.Diagnostics;
using System.Net;
using System.Net.Sockets;
using System.Threading;
using URWPGSim2D.Hosting;
using URWPGSim2D.Engine.Scenario;
using static URWPGSim2D.Server.Viewer.Tests.PageProbe;

namespace URWPGSim2D.Server.Viewer.Tests;

/// <summary>
/// <c>run --live</c> with real browsers. The server starts paused and is driven by steps, so every
/// check waits for a state (bounded), never for an amount of time.
/// </summary>
[Collection(BrowserCollection.Name)]
public sealed class LiveViewTests(Browser browser)
{
    private const int Wait = Browser.HangMs;

    private sealed record Live(string Url, CancellationTokenSource Stop, Task<int> Served, StringWriter Out, StringWriter Error);

    internal static int FreePort()
    {
        var probe = new TcpListener(IPAddress.Loopback, 0);
        probe.Start();
        int port = ((IPEndPoint)probe.LocalEndpoint).Port;
        probe.Stop();
        return port;
    }

    private static async Task<Live> Start(params string[] extra)
    {
        var options = RunOptions.Parse(["--live", "--paused", "--port", FreePort().ToString(System.Globalization.CultureInfo.InvariantCulture), .. extra]);
        var url = new TaskCompletionSource<string>(TaskCreationOptions.RunContinuationsAsynchronously);
        var stop = new CancellationTokenSource();
        var output = new StringWriter();
        var error = new StringWriter();
        var console = new CliConsole(new StringReader(string.Empty), output, error);
        var served = Task.Run(() => LiveRun.Serve(options, DefaultScenario.Load(), new TeamStrategy?[2], console, stop.Token, u => url.TrySetResult(u)));
        var first = await Task.WhenAny(url.Task, served, Task.Delay(Wait));
        Assert.True(first == url.Task, $"the live server did not start: {error}");
        return new Live(await url.Task, stop, served, output, error);
    }

    private static async Task<int> Stop(Live live)
    {
        live.Stop.Cancel();
        Assert.True(await Task.WhenAny(live.Served, Task.Delay(Wait)) == live.Served, "the server did not stop");
        return await live.Served;
    }

    private async Task<(IPage Page, System.Collections.Generic.List<string> Errors)> Open(Live live)
    {
        var (page, errors) = await browser.NewPageAsync();
        await page.GotoAsync(live.Url);
        await page.WaitForFunctionAsync("() => window.urwpg && urwpg.store && urwpg.serverStatus", null, new() { Timeout = Wait });
        return (page, errors);
    }

    // Waits until the page holds the server's cycles 0 … cycle and the server says it is paused at cycle.
    private static Task PausedAt(IPage page, int cycle) =>
        page.WaitForFunctionAsync(
            "c => urwpg.store && urwpg.serverStatus && urwpg.serverStatus.paused && urwpg.serverStatus.cycle === c && urwpg.store.count === c + 1", cycle, new() { Timeout = Wait });

    private static Task<int> Count(IPage page) => page.EvaluateAsync<int>("() => urwpg.store.count");

    private static Task<double[]> Frames(IPage page) => page.EvaluateAsync<double[]>("() => Array.from(urwpg.store.frames.slice(0, urwpg.store.count * urwpg.store.stride))");

    [Fact]
    public async Task AFishsDetailsInTheLivePageAreTheTracesOfTheSameMatch()
    {
        var live = await Start("--speed", "20");
        var (page, errors) = await Open(live);
        await PausedAt(page, 0);
        for (int k = 1; k <= 4; k++)
        {
            await page.ClickAsync("#server-step");
            await PausedAt(page, k);
        }

        await Settle(page);
        var reference = Path.Combine(Path.GetTempPath(), $"urwpg-live-{Guid.NewGuid():N}.jsonl");
        Assert.Equal(0, RecordedMatch.Cli("run", "--item", "default", "--cycles", "4", "--trace", reference).Code);
        var line = System.Text.Json.JsonDocument.Parse(File.ReadAllLines(reference)[4]).RootElement;
        File.Delete(reference);
        for (int i = 0; i < 4; i++)
        {
            await page.SelectOptionAsync("#inspect", "fish" + i);
            var f = line.GetProperty("fish")[i];
            var shown = await page.EvaluateAsync<double[]>("() => { const d = urwpg.details(); return [d.cycle, d.speed, d.angularSpeed, ...d.decision, ...d.gears, d.contacts.length]; }");
            Assert.Equal(
                [4, f.GetProperty("speed").GetSingle(), f.GetProperty("angularSpeed").GetSingle(), f.GetProperty("decision")[0].GetInt32(), f.GetProperty("decision")[1].GetInt32(),
                 f.GetProperty("gears")[0].GetInt32(), f.GetProperty("gears")[1].GetInt32(),
                 line.GetProperty("contacts").EnumerateArray().Count(c => c.GetProperty("a").GetString() == "fish" + i || c.GetProperty("b").GetString() == "fish" + i)],
                shown.Select((v, j) => j is 1 or 2 ? (double)(float)v : v).ToArray());
        }

        await page.SelectOptionAsync("#inspect", "ball4");
        var ball = line.GetProperty("balls")[4].GetProperty("velocity");
        var velocity = await page.EvaluateAsync<double[]>("() => urwpg.details().velocity");
        Assert.Equal([ball[0].GetSingle(), ball[1].GetSingle()], velocity.Select(v => (float)v).ToArray());
        NoErrors(errors);
        await page.Context.CloseAsync();
        Assert.Equal(0, await Stop(live));
    }

    [Fact]
    public async Task ViewersSeeTheSameCyclesPauseHoldsAndStepPlaysOne()
    {
        var live = await Start("--speed", "20");
        Assert.StartsWith("http://127.0.0.1:", live.Url, StringComparison.Ordinal);
        var (one, errorsOne) = await Open(live);
        await PausedAt(one, 0);

        // Each step plays exactly one cycle, which the page receives and shows.
        for (int k = 1; k <= 3; k++)
        {
            await one.ClickAsync("#server-step");
            await PausedAt(one, k);
            await Settle(one);
            Assert.Equal($"cycle {k} / 3000", await one.TextContentAsync("#cycle")); // the match's length, not the last cycle received
        }

        // The stream is the match itself: the same as the trace of the same match.
        var reference = Path.Combine(Path.GetTempPath(), $"urwpg-live-{Guid.NewGuid():N}.jsonl");
        Assert.Equal(0, RecordedMatch.Cli("run", "--item", "default", "--cycles", "3", "--trace", reference).Code);
        var lines = File.ReadAllLines(reference);
        File.Delete(reference);
        var line3 = System.Text.Json.JsonDocument.Parse(lines[3]).RootElement;
        var fish0 = line3.GetProperty("fish")[0].GetProperty("position");
        var frames = await Frames(one);
        int stride = await one.EvaluateAsync<int>("() => urwpg.store.stride");
        Assert.Equal(fish0[0].GetSingle(), (float)frames[3 * stride]);
        Assert.Equal(fish0[1].GetSingle(), (float)frames[(3 * stride) + 1]);

        // A second viewer gets the same cycles from the start.
        var (two, errorsTwo) = await Open(live);
        await PausedAt(two, 3);
        Assert.Equal(frames, await Frames(two));

        // Resume: cycles stream to both; pause: they stop; a step then plays exactly one more.
        await two.ClickAsync("#server-pause");
        await two.WaitForFunctionAsync("() => urwpg.store.count >= 12", null, new() { Timeout = Wait });

        // The button posts "pause" or "resume" from the status its own page last received: wait
        // until viewer one has seen the match resume, or its click would ask to resume again.
        await one.WaitForFunctionAsync("() => urwpg.serverStatus && !urwpg.serverStatus.paused", null, new() { Timeout = Wait });
        await one.ClickAsync("#server-pause");
        await one.WaitForFunctionAsync("() => urwpg.serverStatus.paused && urwpg.store.count === urwpg.serverStatus.cycle + 1", null, new() { Timeout = Wait });
        int held = await one.EvaluateAsync<int>("() => urwpg.serverStatus.cycle");
        await PausedAt(one, held);
        await PausedAt(two, held);
        Assert.Equal(await Frames(one), await Frames(two));
        await two.ClickAsync("#server-step");
        await PausedAt(one, held + 1);
        await PausedAt(two, held + 1);

        // Closing one viewer does not affect the other.
        await one.Context.CloseAsync();
        await two.ClickAsync("#server-step");
        await PausedAt(two, held + 2);
        await two.ClickAsync("#server-step");
        await PausedAt(two, held + 3);

        // Restart: the viewers start over at cycle 0.
        await two.ClickAsync("#server-restart");
        await PausedAt(two, 0);
        Assert.Equal(frames[..stride], (await Frames(two))[..stride]);

        NoErrors(errorsOne);
        NoErrors(errorsTwo);
        await two.Context.CloseAsync();
        Assert.Equal(0, await Stop(live));
        Assert.StartsWith("match: 0 cycles", live.Out.ToString(), StringComparison.Ordinal);
        Assert.Equal(string.Empty, live.Error.ToString());
    }

    [Fact]
    public async Task TheMatchEndsAtItsLastCycleAndTheSummaryCountsWhatWasPlayed()
    {
        var live = await Start("--cycles", "2");
        var (page, errors) = await Open(live);
        await PausedAt(page, 0);
        await page.ClickAsync("#server-step");
        await PausedAt(page, 1);
        await Settle(page);
        Assert.Equal("cycle 1 / 2", await page.TextContentAsync("#cycle"));
        await page.ClickAsync("#server-pause"); // resume: plays the last cycle, then the match is over
        await page.WaitForFunctionAsync("() => urwpg.serverStatus.over && urwpg.serverStatus.cycle === 2 && urwpg.store.count === 3", null, new() { Timeout = Wait });

        // The summary is printed when the match ends, while the page is still served (the server
        // prints it before it tells the viewers the match is over).
        string atEnd = live.Out.ToString();
        Assert.StartsWith("match: 2 cycles, 0.2 s simulated, played live in ", atEnd, StringComparison.Ordinal);
        Assert.EndsWith("match over: the page stays up (restart there plays it again; Ctrl+C to stop)\n", atEnd, StringComparison.Ordinal);
        Assert.False(live.Served.IsCompleted);
        await page.ClickAsync("#server-step");
        await page.WaitForFunctionAsync("() => urwpg.serverStatus.paused && urwpg.serverStatus.over", null, new() { Timeout = Wait });
        Assert.Equal(3, await Count(page));
        await Settle(page);
        Assert.Equal("match over", await page.TextContentAsync("#live-status"));

        // The page is the replay page too: scrub back through what was received.
        await Scrub(page, 1);
        Assert.Equal(1, await Cycle(page));
        Assert.Equal("cycle 1 / 2", await page.TextContentAsync("#cycle")); // scrubbed back; the match's last cycle is 2
        NoErrors(errors);
        await page.Context.CloseAsync();
        Assert.Equal(0, await Stop(live));
        Assert.Equal(atEnd, live.Out.ToString()); // the summary once, not again at Ctrl+C
    }

    [Fact]
    public void APortInUseIsOneErrorLineAndExitCodeTwo()
    {
        var busy = new TcpListener(IPAddress.Loopback, 0);
        busy.Start();
        try
        {
            int port = ((IPEndPoint)busy.LocalEndpoint).Port;
            var (code, stdout, stderr) = RecordedMatch.Cli("run", "--live", "--port", port.ToString(System.Globalization.CultureInfo.InvariantCulture));
            Assert.Equal(2, code);
            Assert.Equal(string.Empty, stdout);
            Assert.StartsWith($"--port {port}: cannot listen on http://127.0.0.1:{port}/ (", stderr, StringComparison.Ordinal);
            Assert.Single(stderr.TrimEnd().Split('\n'));
        }
        finally
        {
            busy.Stop();
        }
    }

    [Fact]
    public async Task CtrlCEndsTheMatchAndTheServerWithTheSummary()
    {
        string server = Path.Combine(AppContext.BaseDirectory, "URWPGSim2D.Server.dll");
        int port = FreePort();
        string host = Environment.GetEnvironmentVariable("DOTNET_HOST_PATH") ?? "dotnet";

        // A shell without job control starts background commands with SIGINT ignored, the runtime
        // keeps an inherited SIG_IGN (as POSIX programs do), and a child inherits it again: a test
        // run started in the background would give a server that cannot hear Ctrl+C. On Linux the
        // server is started with SIGINT back at its default (coreutils' env), whatever started the tests.
        var start = new ProcessStartInfo(OperatingSystem.IsLinux() ? "env" : host)
        {
            RedirectStandardOutput = true,
            RedirectStandardError = true,
            RedirectStandardInput = true,
            UseShellExecute = false,
        };
        if (OperatingSystem.IsLinux())
        {
            start.ArgumentList.Add("--default-signal=INT");
            start.ArgumentList.Add(host);
        }

        foreach (var a in (string[])[server, "run", "--item", "default", "--live", "--paused", "--port", port.ToString(System.Globalization.CultureInfo.InvariantCulture)])
        {
            start.ArgumentList.Add(a);
        }

        using var process = Process.Start(start)!;
        try
        {
            var stderr = process.StandardError.ReadToEndAsync();
            string? first = process.StandardOutput.ReadLine();
            Assert.Equal($"live view: http://127.0.0.1:{port}/ (Ctrl+C to stop)", first);
            using (var kill = Process.Start("kill", ["-INT", process.Id.ToString(System.Globalization.CultureInfo.InvariantCulture)]))
            {
                kill.WaitForExit();
            }

            var rest = process.StandardOutput.ReadToEndAsync();
            Assert.True(process.WaitForExit(Wait), "the server did not end on SIGINT");
            Assert.Equal(0, process.ExitCode);
            Assert.StartsWith("match: 0 cycles", await rest, StringComparison.Ordinal);
            Assert.Contains("\ngoals: team 0 (chase-ball) 0, team 1 (chase-ball) 0\n", await rest, StringComparison.Ordinal);
            Assert.Equal(string.Empty, await stderr);
        }
        finally
        {
            // A failed assertion must not leave a live server behind (it would keep its port and
            // everything it inherited, such as a lock held by the shell that started the tests).
            if (!process.HasExited)
            {
                process.Kill(entireProcessTree: true);
                process.WaitForExit();
            }
        }
    }

    [Fact]
    public async Task The_live_page_shows_the_strategies_drawings_as_they_are_played()
    {
        var live = await Start("--debug-draw");
        var (page, errors) = await Open(live);
        await PausedAt(page, 0);
        for (int k = 1; k <= 3; k++)
        {
            await page.ClickAsync("#server-step");
            await PausedAt(page, k);
        }

        await Settle(page);
        Assert.True(await page.IsVisibleAsync("#show-draw0"));

        // The drawings of each cycle are those of the trace of the same match.
        var reference = Path.Combine(Path.GetTempPath(), $"urwpg-live-draw-{Guid.NewGuid():N}.jsonl");
        Assert.Equal(0, RecordedMatch.Cli("run", "--item", "default", "--cycles", "3", "--debug-draw", "--trace", reference).Code);
        var lines = File.ReadAllLines(reference);
        File.Delete(reference);
        for (int k = 1; k <= 3; k++)
        {
            string expected = System.Text.Json.JsonDocument.Parse(lines[k]).RootElement.GetProperty("draw").GetRawText();
            string shown = await page.EvaluateAsync<string>("k => JSON.stringify(urwpg.drawingsAt(k))", k);
            Assert.True(SameJson(System.Text.Json.JsonDocument.Parse(expected).RootElement, System.Text.Json.JsonDocument.Parse(shown).RootElement), $"cycle {k}: the page shows {shown}, the trace has {expected}");
        }

        NoErrors(errors);
        await page.Context.CloseAsync();
        Assert.Equal(0, await Stop(live));
    }

    [Fact]
    public async Task OnAServerOthersCanReachAPageWithoutTheControlTokenOnlyWatches()
    {
        var live = await Start("--host", "0.0.0.0", "--speed", "20");
        string banner = live.Out.ToString();
        for (var waited = Stopwatch.StartNew(); !banner.Contains("only watch)", StringComparison.Ordinal) && waited.ElapsedMilliseconds < Wait; banner = live.Out.ToString())
        {
            await Task.Delay(20); // the control line follows the first banner line at once
        }

        int at = banner.IndexOf("control: ", StringComparison.Ordinal);
        Assert.True(at >= 0, banner);
        string control = banner[(at + "control: ".Length)..].Split(' ')[0];
        string home = control[..control.IndexOf('?', StringComparison.Ordinal)];

        // Opened as a student would (no token): the match plays on, the buttons are gone, the status says so.
        var (watcher, watcherErrors) = await browser.NewPageAsync();
        await watcher.GotoAsync(home);
        await watcher.WaitForFunctionAsync("() => window.urwpg && urwpg.store && urwpg.serverStatus && urwpg.viewOnly === true", null, new() { Timeout = Wait });
        Assert.False(await watcher.IsVisibleAsync("#server-step"));
        Assert.False(await watcher.IsVisibleAsync("#server-restart"));
        await watcher.WaitForFunctionAsync("() => document.getElementById('live-status').textContent.endsWith('view only')", null, new() { Timeout = Wait });
        Assert.Equal(403, await watcher.EvaluateAsync<int>("() => fetch('control?action=step', { method: 'POST' }).then(r => r.status)"));

        // Opened with the control link: the buttons are there and steer.
        var (teacher, teacherErrors) = await browser.NewPageAsync();
        await teacher.GotoAsync(control);
        await teacher.WaitForFunctionAsync("() => window.urwpg && urwpg.store && urwpg.serverStatus && urwpg.viewOnly === false", null, new() { Timeout = Wait });
        await PausedAt(teacher, 0);
        Assert.True(await teacher.IsVisibleAsync("#server-step"));
        await teacher.ClickAsync("#server-step");
        await PausedAt(teacher, 1);
        await PausedAt(watcher, 1);

        NoErrors(watcherErrors.Where(e => !e.Contains("403", StringComparison.Ordinal)).ToList());
        NoErrors(teacherErrors);
        await watcher.Context.CloseAsync();
        await teacher.Context.CloseAsync();
        Assert.Equal(0, await Stop(live));
    }

    // The same JSON values (numbers compared as numbers: the browser and .NET may print one differently).
    private static bool SameJson(System.Text.Json.JsonElement a, System.Text.Json.JsonElement b) => a.ValueKind == b.ValueKind && a.ValueKind switch
    {
        System.Text.Json.JsonValueKind.Number => a.GetDouble() == b.GetDouble(),
        System.Text.Json.JsonValueKind.String => a.GetString() == b.GetString(),
        System.Text.Json.JsonValueKind.Array => a.GetArrayLength() == b.GetArrayLength() && a.EnumerateArray().Zip(b.EnumerateArray()).All(p => SameJson(p.First, p.Second)),
        System.Text.Json.JsonValueKind.Object => a.EnumerateObject().Count() == b.EnumerateObject().Count()
            && a.EnumerateObject().All(p => b.TryGetProperty(p.Name, out var q) && SameJson(p.Value, q)),
        _ => true,
    };
}
