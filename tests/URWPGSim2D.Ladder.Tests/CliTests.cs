namespace URWPGSim2D.Ladder.Tests;

/// <summary>
/// The command line as a user runs it: <c>ladder serve</c> prints its address and the organiser's
/// token once; <c>team add</c> prints the team's token alone on its last line; <c>submit</c> prints
/// compile errors as <c>run</c> does (exit 2); every bad argument is one line and exit 2.
/// </summary>
public sealed class CliTests : IDisposable
{
    private readonly string _folder = Directory.CreateTempSubdirectory("urwpg-ladder-cli-").FullName;

    public void Dispose() => Directory.Delete(_folder, recursive: true);

    [Fact]
    public async Task ServeAddAndSubmitAsInTheReadme()
    {
        string data = Path.Combine(_folder, "data");
        string admin;
        using (var first = await ServeProcess.StartAsync("ladder", "serve", "--item", "polo-1v1", "--minutes", "1", "--data", data, "--port", "0", "--workers", "0", "--admin-token", "organiser-1"))
        {
            Assert.Matches(@"^ladder: polo-1v1 at http://127\.0\.0\.1:\d+/ \(data: .*, SQLite\); Ctrl\+C stops it$", first.FirstLine);
            var (code, output, error) = await ServeProcess.RunAsync("ladder", "team", "add", "nobody", "--server", first.Url, "--admin-token", "wrong-token");
            Assert.Equal((2, string.Empty, "ladder team add: authorization: this needs the organiser's token (Authorization: Bearer TOKEN)\n"), (code, output, error));
            first.KillHard();
        }

        // The organiser's token is printed on the first start only: read it from a second folder's first start.
        string data2 = Path.Combine(_folder, "data2");
        using var serve = await ServeProcess.StartAsync(readToken: true, "ladder", "serve", "--item", "polo-1v1", "--data", data2, "--port", "0", "--workers", "0");
        admin = serve.TokenLine!;
        Assert.Matches("^[A-Za-z0-9_-]{43}$", admin);

        var added = await ServeProcess.RunAsync("ladder", "team", "add", "Team One", "--server", serve.Url, "--admin-token", admin);
        Assert.Equal((0, string.Empty), (added.Code, added.Error));
        string[] lines = added.Out.TrimEnd('\n').Split('\n');
        Assert.Equal("team Team One added; its token (shown once):", lines[0]);
        Assert.Matches("^[A-Za-z0-9_-]{43}$", lines[^1]);

        string bad = Path.Combine(_folder, "Bad.cs");
        File.WriteAllText(bad, "class X { int y = ; }");
        var failed = await ServeProcess.RunAsync("ladder", "submit", "--server", serve.Url, "--token", lines[^1], bad);
        Assert.Equal((2, string.Empty), (failed.Code, failed.Out));
        Assert.Equal("compiling Bad.cs (1 file)...\ncannot compile Bad.cs: 1 compile error in 1 file:\nBad.cs(1,19): error CS1525: Invalid expression term ';'\n", failed.Error);

        // The final round from the command line: two house entrants can play, so a final of three is refused.
        Assert.Equal(0, (await ServeProcess.RunAsync("ladder", "team", "add", "house", "--server", serve.Url, "--admin-token", admin, "--strategy", "demo")).Code);
        Assert.Equal(0, (await ServeProcess.RunAsync("ladder", "team", "add", "house2", "--server", serve.Url, "--admin-token", admin, "--strategy", "idle")).Code);
        var three = await ServeProcess.RunAsync("ladder", "final", "--server", serve.Url, "--admin-token", admin, "--top", "3");
        Assert.Equal((2, string.Empty, "ladder final: top: 2 teams can play, fewer than 3\n"), (three.Code, three.Out, three.Error));
        var final = await ServeProcess.RunAsync("ladder", "final", "--server", serve.Url, "--admin-token", admin, "--top", "2", "--rounds", "1");
        Assert.Equal((0, "final round started: house, house2; each pair plays 1 match, 1 in all\n", string.Empty), (final.Code, final.Out, final.Error));
    }

    [Theory]
    [InlineData(new[] { "ladder" }, "ladder: a sub-command is needed (serve, create, list, pause, resume, team add, submit, final, worker). Usage: urwpgsim2d ladder serve|create|list|pause|resume|team add|submit|final|worker ...")]
    [InlineData(new[] { "ladder", "serve", "--minutes", "2" }, "ladder serve: --minutes must be 10, 5, 3 or 1, got \"2\"")]
    [InlineData(new[] { "ladder", "serve", "--port", "70000" }, "ladder serve: --port must be a whole number from 0 to 65535, got \"70000\"")]
    [InlineData(new[] { "ladder", "serve", "--workers", "-1" }, "ladder serve: --workers must be a whole number from 0 to 256, got \"-1\"")]
    [InlineData(new[] { "ladder", "serve", "--admin-token", "short" }, "ladder serve: --admin-token must be at least 8 characters, got 5")]
    [InlineData(new[] { "ladder", "serve", "--takeover", "5", "--database", "Host=x;Database=y" }, "ladder serve: --takeover must be a whole number from 10 to 86400, got \"5\"")]
    [InlineData(new[] { "ladder", "serve", "--takeover", "1m" }, "ladder serve: --takeover must be a whole number from 10 to 86400, got \"1m\"")]
    [InlineData(new[] { "ladder", "serve", "--takeover", "30", "--port", "0", "--data", "/nonexistent/never" }, "ladder serve: --takeover: only with --database (PostgreSQL), where worker processes take matches over")]
    [InlineData(new[] { "ladder", "team", "add", "x", "--server", "http://127.0.0.1:1/", "--admin-token", "t", "--strategy", "best" }, "ladder team add: --strategy must be demo, chase-ball or idle, got \"best\"")]
    [InlineData(new[] { "ladder", "submit", "--server", "ftp://x/", "--token", "t", "x.cs" }, "ladder submit: --server must be an http:// or https:// address, got \"ftp://x/\"")]
    [InlineData(new[] { "ladder", "submit", "--server", "http://127.0.0.1:1/", "--token", "t", "nothing.txt" }, "ladder submit: PATH must be a folder of .cs files, a .cs file or a .dll, got \"nothing.txt\"")]
    [InlineData(new[] { "ladder", "final", "--server", "http://127.0.0.1:1/", "--admin-token", "t", "--top", "1" }, "ladder final: --top must be a whole number from 2 to 1000, got \"1\"")]
    [InlineData(new[] { "ladder", "worker", "--database", "Host=x;Database=y", "--workers", "0" }, "ladder worker: --workers must be a whole number from 1 to 256, got \"0\"")]
    [InlineData(new[] { "ladder", "worker", "--data", "x" }, "ladder worker: --database CONNECTION is required. Usage: urwpgsim2d ladder worker --database CONNECTION [--data DIR] [--workers N]")]
    [InlineData(new[] { "ladder", "final", "--server", "http://127.0.0.1:1/", "--admin-token", "t" }, "ladder final: --top K is required. Usage: urwpgsim2d ladder final --server URL --admin-token T --top K [--rounds N] [--ladder L]")]
    public async Task BadArgumentsAreOneLineAndExitTwo(string[] arguments, string message)
    {
        var (code, output, error) = await ServeProcess.RunAsync(arguments);
        Assert.Equal((2, string.Empty, message + "\n"), (code, output, error));
    }

    [Fact]
    public async Task AnUnknownOptionOfASubCommandIsNamed()
    {
        var (code, _, error) = await ServeProcess.RunAsync("ladder", "serve", "--itme", "polo-1v1");
        Assert.Equal((2, "ladder serve: unknown option \"--itme\"; did you mean --item?\n"), (code, error));
    }

    [Fact]
    public async Task TheHelpShowsTheThreeUsageLines()
    {
        var (code, output, _) = await ServeProcess.RunAsync("ladder", "--help");
        Assert.Equal(0, code);
        Assert.Contains("urwpgsim2d ladder serve [--item ITEM] [--minutes M] [--data DIR] [--database CONNECTION] [--port P] [--host H] [--admin-token TOKEN] [--workers N] [--takeover S]\n", output, StringComparison.Ordinal);
        Assert.Contains("urwpgsim2d ladder team add NAME --server URL --admin-token T [--strategy demo|chase-ball|idle] [--ladder L]\n", output, StringComparison.Ordinal);
        Assert.Contains("urwpgsim2d ladder submit --server URL --token T [--ladder L] PATH\n", output, StringComparison.Ordinal);
        Assert.Contains("urwpgsim2d ladder final --server URL --admin-token T --top K [--rounds N] [--ladder L]\n", output, StringComparison.Ordinal);
        Assert.Contains("urwpgsim2d ladder worker --database CONNECTION [--data DIR] [--workers N]\n", output, StringComparison.Ordinal);
    }
}
