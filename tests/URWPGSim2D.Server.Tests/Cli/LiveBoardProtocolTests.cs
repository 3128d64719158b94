using System.Net.Http;

namespace URWPGSim2D.Server.Tests.Cli;

/// <summary>
/// The control board over HTTP, as the page uses it: <c>GET /board</c>, <c>POST /control?action=start…</c>
/// (refusals are 400 with the reason), the match it starts streamed on <c>/events</c>, and
/// <c>GET /replay.html</c>, which for a whole match is the page <c>run --html</c> writes. Without
/// <c>--strategies</c> the live view is as it was: no board, the same refusal of an unknown action.
/// </summary>
public sealed class LiveBoardProtocolTests : IDisposable
{
    private static readonly TimeSpan Wait = TimeSpan.FromSeconds(60);
    private readonly string _folder = Path.Combine(Path.GetTempPath(), "urwpg-board-http-" + Guid.NewGuid().ToString("N"));
    private readonly HttpClient _http = new() { Timeout = Wait };

    public LiveBoardProtocolTests()
    {
        Directory.CreateDirectory(_folder);
        File.WriteAllText(Path.Combine(_folder, "gamma.cs"), LiveBoardTests.Named("gamma"));
    }

    public void Dispose()
    {
        _http.Dispose();
        Directory.Delete(_folder, recursive: true);
    }

    private sealed record Server(string Url, CancellationTokenSource Stop, Task<int> Served, LiveRunTests.SignallingWriter Out) : IAsyncDisposable
    {
        public async ValueTask DisposeAsync()
        {
            Stop.Cancel();
            Assert.True(await Task.WhenAny(Served, Task.Delay(Wait)) == Served, "the server did not stop");
            Assert.Equal(0, await Served);
            Stop.Dispose();
        }
    }

    private static async Task<Server> Start(params string[] arguments)
    {
        var options = RunOptions.Parse(["--live", "--port", LiveRunTests.FreePort().ToString(CultureInfo.InvariantCulture), .. arguments]);
        var scenario = options.Item == "default" ? DefaultScenario.Load() : ItemRegistry.Find(options.Item ?? RunCommand.MainItem)!.CreateScenario(1);
        var url = new TaskCompletionSource<string>(TaskCreationOptions.RunContinuationsAsynchronously);
        var output = new LiveRunTests.SignallingWriter("match over");
        var console = new CliConsole(new StringReader(string.Empty), output, TextWriter.Synchronized(new StringWriter()));
        var stop = new CancellationTokenSource();
        var served = Task.Run(() => LiveRun.Serve(options, scenario, RunCommand.LoadTeams(options), console, stop.Token, u => url.TrySetResult(u)));
        Assert.True(await Task.WhenAny(url.Task, served, Task.Delay(Wait)) == url.Task, "the live server did not start");
        return new Server(await url.Task, stop, served, output);
    }

    private async Task<(HttpStatusCode Status, string Text)> Post(Server server, string query)
    {
        using var response = await _http.PostAsync(server.Url + "control?" + query, null);
        return (response.StatusCode, await response.Content.ReadAsStringAsync());
    }

    // Reads the event stream until a cycle-0 line of the given item arrives; returns it.
    private async Task<JsonElement> FirstLineOf(Server server, string item)
    {
        using var cancel = new CancellationTokenSource(Wait);
        using var stream = await _http.GetStreamAsync(server.Url + "events", cancel.Token);
        using var reader = new StreamReader(stream);
        while (await reader.ReadLineAsync(cancel.Token) is { } line)
        {
            if (line.StartsWith("data: {\"cycle\":0,", StringComparison.Ordinal))
            {
                var json = JsonDocument.Parse(line["data: ".Length..]).RootElement;
                if (json.GetProperty("item").GetString() == item)
                {
                    return json.Clone();
                }
            }
        }

        throw new InvalidOperationException("the event stream ended");
    }

    [Fact]
    public async Task TheBoardListsItsChoicesStartsAChosenMatchAndRefusesABadOne()
    {
        await using var server = await Start("--paused", "--item", "default", "--cycles", "5", "--strategies", _folder);
        var board = JsonDocument.Parse(await _http.GetStringAsync(server.Url + "board")).RootElement;
        Assert.Equal(_folder, board.GetProperty("folder").GetString());
        Assert.Equal(["gamma.cs"], board.GetProperty("strategies").EnumerateArray().Select(e => e.GetString()));
        Assert.Equal(["scene", "demo", "idle", "chase-ball"], board.GetProperty("builtIns").EnumerateArray().Select(e => e.GetString()));
        Assert.Equal(["default", .. ItemRegistry.All.Select(i => i.Slug)], board.GetProperty("items").EnumerateArray().Select(e => e.GetProperty("id").GetString()));
        var current = board.GetProperty("current");
        Assert.Equal(("default", 5, 2), (current.GetProperty("item").GetString(), current.GetProperty("cycles").GetInt32(), current.GetProperty("teams").GetArrayLength()));

        var refused = await Post(server, "action=start&item=polo-1v1&minutes=2");
        Assert.Equal((HttpStatusCode.BadRequest, "start: minutes must be 10, 5, 3 or 1, got \"2\"\n"), refused);
        Assert.Equal(HttpStatusCode.BadRequest, (await Post(server, "action=fly")).Status);

        var started = FirstLineOf(server, "polo-1v1");
        var ok = await Post(server, "action=start&item=polo-1v1&minutes=1&team0=gamma.cs&team1=chase-ball");
        Assert.Equal(HttpStatusCode.OK, ok.Status);
        var line = await started;
        Assert.Equal(["gamma [gamma.cs]", "chase-ball"], line.GetProperty("layout").GetProperty("teams").EnumerateArray().Select(t => t.GetProperty("name").GetString()));
        current = JsonDocument.Parse(await _http.GetStringAsync(server.Url + "board")).RootElement.GetProperty("current");
        Assert.Equal(("polo-1v1", 1, "gamma.cs"), (current.GetProperty("item").GetString(), current.GetProperty("minutes").GetInt32(), current.GetProperty("teams")[0].GetString()));
    }

    [Fact]
    public async Task AWholeMatchSavedFromTheLiveViewIsThePageRunHtmlWrites()
    {
        await using var server = await Start("--item", "default", "--cycles", "6", "--speed", "1000", "--strategies", _folder);

        // The summary is printed once the last cycle is published: then the page holds the whole match.
        Assert.True(await Task.WhenAny(server.Out.Seen, server.Served, Task.Delay(Wait)) == server.Out.Seen, "the match did not end: " + server.Out);
        using var response = await _http.GetAsync(server.Url + "replay.html");
        Assert.Equal(HttpStatusCode.OK, response.StatusCode);
        Assert.Equal("attachment; filename=\"match-cycle6.html\"", response.Content.Headers.ContentDisposition?.ToString());
        string html = await response.Content.ReadAsStringAsync();

        string file = Path.Combine(_folder, "match.html");
        Assert.Equal(0, CliRun.Of(string.Empty, "run", "--item", "default", "--cycles", "6", "--html", file).ExitCode);
        Assert.Equal(File.ReadAllText(file), html);
    }

    [Fact]
    public async Task WithoutStrategiesTheLiveViewHasNoBoard()
    {
        await using var server = await Start("--paused", "--item", "default");
        using (var response = await _http.GetAsync(server.Url + "board"))
        {
            Assert.Equal(HttpStatusCode.NotFound, response.StatusCode);
        }

        Assert.Equal((HttpStatusCode.BadRequest, "unknown action (pause, resume, step or restart)"), await Post(server, "action=start&item=default"));
        Assert.Contains("<script type=\"application/json\" id=\"match-data\">{\"live\":true}</script>", await _http.GetStringAsync(server.Url), StringComparison.Ordinal); // the page offers no board
    }
}
