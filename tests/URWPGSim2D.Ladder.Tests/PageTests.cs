using System.Text.RegularExpressions;
using URWPGSim2D.Server.Viewer.Tests;

namespace URWPGSim2D.Ladder.Tests;

/// <summary>
/// The pages in Chromium, as people use them: the organiser signs in and adds a house entrant and
/// three teams; two teams sign in and submit through their page, the third with the command line;
/// ranked matches play; the standings page, never reloaded, fills in and puts the known strongest
/// (the item's demo, which scores in water polo 1v1 where a fish that does not move cannot) first.
/// Then a match's page shows the replay, and the queue names the submissions. And an organiser
/// creates a second ladder on the organiser's page, chooses it, adds its house entrants, and the
/// ladders' overview shows both ladders and the second one's matches and standings.
/// </summary>
public sealed class PageTests : IClassFixture<Browser>, IAsyncLifetime
{
    private readonly Browser _browser;
    private readonly string _sources = Directory.CreateTempSubdirectory("urwpg-ladder-pages-").FullName;
    private LadderHost _host = null!;

    public PageTests(Browser browser) => _browser = browser;

    public async Task InitializeAsync() => _host = await LadderHost.StartAsync(workers: 1);

    public async Task DisposeAsync()
    {
        await _host.DisposeAsync();
        Directory.Delete(_sources, recursive: true);
    }

    // A team whose fish do not move.
    private static readonly string Still = URWPGSim2D.Testing.SdkStrategy.Source("Still", "still", "d.Fill(Decision.Stop);");

    private string Url(string path) => _host.Server.Url.TrimEnd('/') + path;

    private async Task<string> AddTeam(IPage page, string name, string? house)
    {
        await page.FillAsync("#add-team input[name=name]", name);
        await page.SelectOptionAsync("#add-team select[name=strategy]", house ?? string.Empty);
        await page.ClickAsync("#add-team button");
        var shown = page.Locator("#team-token");
        await Assertions.Expect(shown).ToContainTextAsync($"team {name} added", new() { Timeout = Browser.HangMs });
        return Regex.Match(await shown.InnerTextAsync(), "([A-Za-z0-9_-]{43})$").Groups[1].Value;
    }

    private static async Task<string> SignInResult(IPage page) =>
        await page.Locator("#signin-result").CountAsync() > 0 ? await page.InnerTextAsync("#signin-result") : "(no sign-in form on this page)";

    private async Task SubmitThroughThePage(string token, string expectedName, string file)
    {
        var (page, errors) = await _browser.NewPageAsync();
        await page.GotoAsync(Url("/"));
        await page.FillAsync("#signin input[name=token]", token);
        await page.ClickAsync("#signin button");
        // Signed in, the page moves to the team's page; refused, it says why under the form.
        try
        {
            await page.WaitForFunctionAsync(
                "name => location.pathname === '/teams/' + name || (document.getElementById('signin-result')?.textContent ?? '') !== ''",
                expectedName, new() { Timeout = Browser.HangMs, PollingInterval = 100 });
        }
        catch (TimeoutException)
        {
            Assert.Fail($"sign-in as {expectedName}: neither the team's page nor a refusal after {Browser.HangMs} ms; at {page.Url}, page errors: {string.Join(" | ", errors)}");
        }

        Assert.True(page.Url == Url("/teams/" + expectedName), $"sign-in as {expectedName} stayed on {page.Url}: {await SignInResult(page)}");
        await page.WaitForLoadStateAsync(LoadState.Load, new() { Timeout = Browser.HangMs });
        await Assertions.Expect(page.Locator("#upload")).ToBeVisibleAsync(new() { Timeout = Browser.HangMs });
        await page.SetInputFilesAsync("#submit input[type=file]", file);
        await page.ClickAsync("#submit button");
        await Assertions.Expect(page.Locator("#submit-log")).ToContainTextAsync("submission ", new() { Timeout = Browser.HangMs });
        string log = await page.InnerTextAsync("#submit-log");
        Assert.True(log.Contains(": ok", StringComparison.Ordinal), log);
        Assert.Empty(errors);
        await page.Context.CloseAsync();
    }

    // The organiser's page, signed in, showing the service's one ladder.
    private async Task<(IPage Page, List<string> Errors)> SignInAsOrganiser()
    {
        var (organiser, errors) = await _browser.NewPageAsync();
        await organiser.GotoAsync(Url("/organiser"));
        await organiser.FillAsync("#admin-signin input[name=token]", LadderHost.AdminToken);
        await organiser.ClickAsync("#admin-signin button");
        await Assertions.Expect(organiser.Locator("#admin")).ToBeVisibleAsync(new() { Timeout = Browser.HangMs });
        await Assertions.Expect(organiser.Locator("#ladder")).ToContainTextAsync("polo-1v1, 600 cycles a match, playing", new() { Timeout = Browser.HangMs });
        return (organiser, errors);
    }

    [Fact]
    public async Task AnOrganiserAndThreeTeamsRunALadderInTheBrowser()
    {
        var (organiser, errors) = await SignInAsOrganiser();

        await AddTeam(organiser, "champion", "demo");
        string alpha = await AddTeam(organiser, "alpha", null);
        string beta = await AddTeam(organiser, "beta", null);
        string gamma = await AddTeam(organiser, "gamma", null);

        // The standings page is opened once and never reloaded from here on.
        var (standings, standingsErrors) = await _browser.NewPageAsync();
        await standings.GotoAsync(Url("/"));

        string file = Path.Combine(_sources, "Still.cs");
        File.WriteAllText(file, Still);
        await SubmitThroughThePage(alpha, "alpha", file);
        await SubmitThroughThePage(gamma, "gamma", file);
        Directory.CreateDirectory(Path.Combine(_sources, "beta"));
        File.WriteAllText(Path.Combine(_sources, "beta", "Still.cs"), Still);
        var cli = await ServeProcess.RunAsync("ladder", "submit", "--server", _host.Server.Url, "--token", beta, Path.Combine(_sources, "beta"));
        Assert.True(cli.Code == 0, cli.Error);

        // Every team has played: four rows, each with at least three games.
        await standings.WaitForFunctionAsync(
            "() => { const rows = [...document.querySelectorAll('#standings tbody tr')]; return rows.length === 4 && rows.every(r => Number(r.children[4].textContent) >= 3); }",
            null, new() { Timeout = Browser.HangMs, PollingInterval = 200 });
        Assert.Equal("champion", await standings.InnerTextAsync("#standings tbody tr:first-child td:nth-child(2)"));
        Assert.Equal("0", await standings.InnerTextAsync("#standings tbody tr:first-child td:nth-child(8)")); // the champion lost none
        await Figures.Shoot(standings, "ladder-standings.png", _sources);

        // A match of a team: its page shows the replay viewer.
        var (match, matchErrors) = await _browser.NewPageAsync();
        await match.GotoAsync(Url("/teams/alpha"));
        var link = match.Locator("#matches tbody tr td a").First;
        await Assertions.Expect(link).ToBeVisibleAsync(new() { Timeout = Browser.HangMs });
        await link.ClickAsync();
        await Assertions.Expect(match.Locator("#replay")).ToBeVisibleAsync(new() { Timeout = Browser.HangMs });
        await Assertions.Expect(match.Locator("#title")).ToContainTextAsync("alpha", new() { Timeout = Browser.HangMs });

        // The queue names the submission each match plays with.
        await match.GotoAsync(Url("/queue"));
        await Assertions.Expect(match.Locator("#done tbody tr").First).ToContainTextAsync("#", new() { Timeout = Browser.HangMs });

        Assert.Empty(errors);
        Assert.Empty(standingsErrors);
        Assert.Empty(matchErrors);
    }

    [Fact]
    public async Task AnOrganiserCreatesASecondLadderOnThePage()
    {
        var (organiser, errors) = await SignInAsOrganiser();

        await organiser.SelectOptionAsync("#create-ladder select[name=item]", "ball-grab");
        await organiser.SelectOptionAsync("#create-ladder select[name=minutes]", "1");
        await organiser.FillAsync("#create-ladder input[name=firstSeed]", "40");
        await organiser.ClickAsync("#create-ladder button");
        await Assertions.Expect(organiser.Locator("#ladder-result")).ToHaveTextAsync("ladder 2 created: ball-grab, 600 cycles a match, first seed 40", new() { Timeout = Browser.HangMs });
        await Assertions.Expect(organiser.Locator("#ladder")).ToHaveTextAsync("this service runs 2 ladders: choose one", new() { Timeout = Browser.HangMs });

        // Chosen, the second ladder is the one the organiser's actions act on.
        await organiser.SelectOptionAsync("#ladder-choice", "2");
        await Assertions.Expect(organiser).ToHaveURLAsync(Url("/organiser?ladder=2"), new() { Timeout = Browser.HangMs });
        await Assertions.Expect(organiser.Locator("#ladder")).ToContainTextAsync("ball-grab, 600 cycles a match, playing", new() { Timeout = Browser.HangMs });
        await AddTeam(organiser, "grabber", "demo");
        await AddTeam(organiser, "sitter", "idle");

        // The standings page without a ladder named goes to the overview: both ladders, the second one playing.
        var (overview, overviewErrors) = await _browser.NewPageAsync();
        await overview.GotoAsync(Url("/"));
        await Assertions.Expect(overview).ToHaveURLAsync(Url("/ladders"), new() { Timeout = Browser.HangMs });
        await overview.WaitForFunctionAsync(
            "() => { const rows = [...document.querySelectorAll('#ladders tbody tr')]; return rows.length === 2 && Number(rows[1].children[5].textContent) >= 1; }",
            null, new() { Timeout = Browser.HangMs, PollingInterval = 200 });
        Assert.Equal(["polo-1v1", "ball-grab"], await overview.Locator("#ladders tbody tr td:nth-child(2)").AllInnerTextsAsync());
        Assert.Equal("0", await overview.InnerTextAsync("#ladders tbody tr:first-child td:nth-child(6)")); // the first ladder has no team

        await overview.ClickAsync("#ladders tbody tr:nth-child(2) td:nth-child(2) a");
        await Assertions.Expect(overview).ToHaveURLAsync(Url("/?ladder=2"), new() { Timeout = Browser.HangMs });
        await Assertions.Expect(overview.Locator("#item")).ToHaveTextAsync("ball-grab", new() { Timeout = Browser.HangMs });
        await overview.WaitForFunctionAsync("() => document.querySelectorAll('#standings tbody tr').length === 2", null, new() { Timeout = Browser.HangMs, PollingInterval = 200 });
        Assert.Equal(["grabber", "sitter"], (await overview.Locator("#standings tbody tr td:nth-child(2)").AllInnerTextsAsync()).Order(StringComparer.Ordinal));
        Assert.Equal(Url("/queue?ladder=2"), await overview.EvaluateAsync<string>("() => document.querySelector('nav a[href*=queue]').href"));

        Assert.Empty(errors);
        Assert.Empty(overviewErrors);
    }
}
