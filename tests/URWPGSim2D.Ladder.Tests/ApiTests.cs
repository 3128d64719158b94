namespace URWPGSim2D.Ladder.Tests;

/// <summary>The JSON API's guards: who may do what, bad input as HTTP 400 with one JSON line, cross-site requests refused, a team's logs its own. No worker runs: nothing here waits for a match.</summary>
public sealed class ApiTests : IAsyncLifetime
{
    private LadderHost _host = null!;

    public async Task InitializeAsync() => _host = await LadderHost.StartAsync(workers: 0);

    public async Task DisposeAsync() => await _host.DisposeAsync();

    private Task<(int Status, JsonElement Body)> AddTeam(string json, string? token = LadderHost.AdminToken, string? origin = null) =>
        _host.Send(HttpMethod.Post, "/api/teams", token, json, origin: origin);

    private static string Error(JsonElement body) => body.GetProperty("error").GetString()!;

    [Fact]
    public async Task OnlyTheOrganiserAddsTeams()
    {
        var none = await AddTeam("{\"name\": \"a\"}", token: null);
        Assert.Equal((401, "authorization: this needs the organiser's token (Authorization: Bearer TOKEN)"), (none.Status, Error(none.Body)));

        var added = await AddTeam("{\"name\": \"a\"}");
        Assert.Equal(201, added.Status);
        string teamToken = added.Body.GetProperty("token").GetString()!;

        var byTeam = await AddTeam("{\"name\": \"b\"}", token: teamToken);
        Assert.Equal(401, byTeam.Status);
        Assert.Equal(401, (await _host.Send(HttpMethod.Post, "/api/ladder/pause", teamToken)).Status);
    }

    [Theory]
    [InlineData("{\"name\": \"\"}", "name must be 1 to 40 letters, digits, spaces, '-', '_' or '.', got \"\"")]
    [InlineData("{\"name\": \"a/b\"}", "name must be 1 to 40 letters, digits, spaces, '-', '_' or '.', got \"a/b\"")]
    [InlineData("{\"name\": 5}", "name must be a string, got 5")]
    [InlineData("{}", "name is required")]
    [InlineData("{\"name\": \"h\", \"strategy\": \"best\"}", "strategy must be demo, chase-ball, idle, got \"best\"")]
    [InlineData("[1]", "body must be a JSON object")]
    public async Task BadInputIsOneJsonLineWith400(string json, string message)
    {
        var answer = await AddTeam(json);
        Assert.Equal((400, message), (answer.Status, Error(answer.Body)));
    }

    [Fact]
    public async Task ATeamNameIsTakenOnce()
    {
        Assert.Equal(201, (await AddTeam("{\"name\": \"twice\"}")).Status);
        var again = await AddTeam("{\"name\": \"twice\"}");
        Assert.Equal((400, "name: a team named \"twice\" exists already"), (again.Status, Error(again.Body)));
    }

    [Fact]
    public async Task ACrossSiteRequestChangesNothing()
    {
        var answer = await AddTeam("{\"name\": \"csrf\"}", origin: "http://evil.example");
        Assert.Equal((403, "origin: a request from http://evil.example may not change this ladder"), (answer.Status, Error(answer.Body)));
        Assert.Equal(404, (await _host.Get("/api/teams/csrf")).Status);

        // The ladder's own pages send their origin: accepted.
        var own = await AddTeam("{\"name\": \"same\"}", origin: _host.Server.Url.TrimEnd('/'));
        Assert.Equal(201, own.Status);
    }

    [Fact]
    public async Task QueryFieldsAreChecked()
    {
        var state = await _host.Get("/api/matches?state=finished");
        Assert.Equal((400, "state must be queued, running or done (comma-separated), got \"finished\""), (state.Status, Error(state.Body)));
        var limit = await _host.Get("/api/matches?limit=0");
        Assert.Equal((400, "limit must be a whole number from 1 to 10000, got \"0\""), (limit.Status, Error(limit.Body)));
        var id = await _host.Get("/api/matches/x1");
        Assert.Equal((400, "match must be a match id (a whole number ≥ 1), got \"x1\""), (id.Status, Error(id.Body)));
        Assert.Equal((404, "match: not found"), ((await _host.Get("/api/matches/99")).Status, Error((await _host.Get("/api/matches/99")).Body)));
    }

    [Fact]
    public async Task AHouseEntrantTakesNoSubmissionAndTokensAreKeptHashed()
    {
        var added = await AddTeam("{\"name\": \"house\", \"strategy\": \"idle\"}");
        string token = added.Body.GetProperty("token").GetString()!;
        using var form = new MultipartFormDataContent { { new ByteArrayContent(Encoding.UTF8.GetBytes("class A {}")), "file", "A.cs" } };
        var answer = await _host.Send(HttpMethod.Post, "/api/submissions", token, content: form);
        Assert.Equal((400, "team \"house\" is a house entrant (idle); it takes no submissions"), (answer.Status, Error(answer.Body)));

        var db = await System.IO.File.ReadAllBytesAsync(System.IO.Path.Combine(_host.Folder, "ladder.db"));
        Assert.Equal(-1, Encoding.ASCII.GetString(db).IndexOf(token, StringComparison.Ordinal)); // only its hash is stored
    }

    [Fact]
    public async Task PasswordSignInGivesASessionOfThatTeam()
    {
        var added = await AddTeam("{\"name\": \"pw\"}");
        string token = added.Body.GetProperty("token").GetString()!;
        Assert.Equal(400, (await _host.Send(HttpMethod.Post, "/api/password", token, "{\"password\": \"short\"}")).Status);
        Assert.Equal(200, (await _host.Send(HttpMethod.Post, "/api/password", token, "{\"password\": \"a long secret\"}")).Status);

        var wrong = await _host.Send(HttpMethod.Post, "/api/signin", null, "{\"name\": \"pw\", \"password\": \"a long secreT\"}");
        Assert.Equal((401, "signin: wrong team name or password"), (wrong.Status, Error(wrong.Body)));
        var right = await _host.Send(HttpMethod.Post, "/api/signin", null, "{\"name\": \"pw\", \"password\": \"a long secret\"}");
        Assert.Equal(200, right.Status);
        var me = await _host.Get("/api/me", right.Body.GetProperty("token").GetString());
        Assert.Equal(("team", "pw"), (me.Body.GetProperty("role").GetString(), me.Body.GetProperty("name").GetString()));
    }

    [Fact]
    public async Task ACompileErrorIsShownToTheTeamOnly()
    {
        var added = await AddTeam("{\"name\": \"coder\"}");
        string token = added.Body.GetProperty("token").GetString()!;
        using var form = new MultipartFormDataContent { { new ByteArrayContent(Encoding.UTF8.GetBytes("class X { int y = ; }")), "file", "Bad.cs" } };
        var answer = await _host.Send(HttpMethod.Post, "/api/submissions", token, content: form);
        Assert.Equal((422, "error"), (answer.Status, answer.Body.GetProperty("state").GetString()));
        string log = answer.Body.GetProperty("log").GetString()!;
        Assert.Contains("Bad.cs(1,19): error CS1525: Invalid expression term ';'", log, StringComparison.Ordinal);
        Assert.DoesNotContain(_host.Folder, log, StringComparison.Ordinal); // the server's folders stay its own

        var own = await _host.Get("/api/teams/coder", token);
        Assert.Contains("error CS1525", own.Body.GetProperty("submissions")[0].GetProperty("log").GetString(), StringComparison.Ordinal);
        var stranger = await _host.Get("/api/teams/coder");
        Assert.False(stranger.Body.GetProperty("submissions")[0].TryGetProperty("log", out _));
    }

    [Fact]
    public async Task SubmissionsPerDayAreLimited()
    {
        Assert.Equal(200, (await _host.Send(HttpMethod.Post, "/api/settings", LadderHost.AdminToken, "{\"submissionsPerDay\": 1}")).Status);
        var added = await AddTeam("{\"name\": \"eager\"}");
        string token = added.Body.GetProperty("token").GetString()!;
        using var first = new MultipartFormDataContent { { new ByteArrayContent(Encoding.UTF8.GetBytes("class X { int y = ; }")), "file", "Bad.cs" } };
        Assert.Equal(422, (await _host.Send(HttpMethod.Post, "/api/submissions", token, content: first)).Status);
        using var second = new MultipartFormDataContent { { new ByteArrayContent(Encoding.UTF8.GetBytes("class X { }")), "file", "X.cs" } };
        var refused = await _host.Send(HttpMethod.Post, "/api/submissions", token, content: second);
        Assert.Equal((400, "submission: the limit of 1 submissions a day is reached; try again after 00:00 UTC"), (refused.Status, Error(refused.Body)));
        Assert.Equal(200, (await _host.Send(HttpMethod.Post, "/api/settings", LadderHost.AdminToken, "{\"submissionsPerDay\": 20}")).Status);
    }

    [Fact]
    public async Task AnUploadJustOverTheLimitIsRefusedWithItsSize()
    {
        var added = await AddTeam("{\"name\": \"big\"}");
        string token = added.Body.GetProperty("token").GetString()!;
        long size = new LadderLimits().MaxUploadBytes + 1000;
        using var form = new MultipartFormDataContent { { new ByteArrayContent(new byte[size]), "file", "Big.cs" } };
        var answer = await _host.Send(HttpMethod.Post, "/api/submissions", token, content: form);
        Assert.Equal((400, $"upload: {size} bytes, more than the limit of {new LadderLimits().MaxUploadBytes}"), (answer.Status, Error(answer.Body)));
        Assert.Empty(System.IO.Directory.GetFileSystemEntries(System.IO.Path.Combine(_host.Folder, "submissions")));
    }

    [Fact]
    public async Task AHugeUploadIsRefusedBeforeItsBodyIsRead()
    {
        var added = await AddTeam("{\"name\": \"huge\"}");
        string token = added.Body.GetProperty("token").GetString()!;
        var uri = new Uri(_host.Server.Url);
        using var tcp = new System.Net.Sockets.TcpClient();
        await tcp.ConnectAsync(uri.Host, uri.Port);
        using var stream = tcp.GetStream();
        string head = $"POST /api/submissions HTTP/1.1\r\nHost: {uri.Authority}\r\nAuthorization: Bearer {token}\r\n" +
            "Content-Type: multipart/form-data; boundary=b\r\nContent-Length: 1000000000\r\nConnection: close\r\n\r\n";
        await stream.WriteAsync(Encoding.ASCII.GetBytes(head)); // the header alone: a gigabyte announced, none sent
        using var reader = new System.IO.StreamReader(stream, Encoding.UTF8);
        string answer = await reader.ReadToEndAsync();
        Assert.StartsWith("HTTP/1.1 413", answer, StringComparison.Ordinal);
        Assert.Contains("\r\n{\"error\":\"upload: larger than the limit of the upload size\"}\r\n", answer, StringComparison.Ordinal);
    }
}
