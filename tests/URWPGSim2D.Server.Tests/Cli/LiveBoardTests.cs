using System.Collections.Specialized;
using URWPGSim2D.Engine.Matches;
using URWPGSim2D.Viewer;

namespace URWPGSim2D.Server.Tests.Cli;

/// <summary>
/// The live view's control board on the server's side: a start is checked (item, length, each
/// team's choice) before anything changes, loads the strategies as <c>run --strategy</c> does and
/// refuses with the lines the command line prints; restart replays the loaded strategies, recompile
/// loads them again from their (edited) files.
/// </summary>
public sealed class LiveBoardTests : TempFolderTest
{
    public LiveBoardTests()
        : base("urwpg-board-")
    {
        Directory.CreateDirectory(Path.Combine(Folder, "alpha"));
        File.WriteAllText(Path.Combine(Folder, "alpha", "Strategy.cs"), Named("alpha-1"));
        File.WriteAllText(Path.Combine(Folder, "beta.cs"), Named("beta"));
    }

    // An SDK strategy that swims straight and calls itself name.
    internal static string Named(string name) => $$"""
        using System;
        using URWPGSim2D.Strategies;
        namespace BoardTeam
        {
            public sealed class Named : IStrategy
            {
                public string TeamName => "{{name}}";
                public void Decide(MatchSnapshot snapshot, ReadOnlySpan<int> fish, Span<Decision> decisions)
                {
                    for (int i = 0; i < decisions.Length; i++) decisions[i] = new Decision(10, 7);
                }
            }
        }
        """;

    private (LiveBoard Board, Counter Starts) Board(params string[] extra)
    {
        var options = RunOptions.Parse(["--live", "--strategies", Folder, .. extra]);
        var scenario = options.Item == "default" ? URWPGSim2D.Engine.Scenario.DefaultScenario.Load() : ItemRegistry.Find(options.Item ?? RunCommand.MainItem)!.CreateScenario(1);
        var console = new CliConsole(new StringReader(string.Empty), new StringWriter(), new StringWriter());
        return (new LiveBoard(options, scenario, RunCommand.LoadTeams(options), console), new Counter());
    }

    private static NameValueCollection Query(params (string Key, string Value)[] pairs)
    {
        var q = new NameValueCollection();
        foreach (var (key, value) in pairs)
        {
            q[key] = value;
        }

        return q;
    }

    private static LiveReply Send(LiveBoard board, Counter counter, string action, params (string Key, string Value)[] pairs) =>
        board.Control(action, Query([("action", action), .. pairs]), counter.Start, counter.Restart) ?? throw new InvalidOperationException("not a board action");

    // The item, length and team labels of the match the board builds next (its strategy hosts stopped again).
    private static (string Item, int Cycles, string[] Teams) Played(LiveBoard board)
    {
        var settings = board.Next();
        var match = settings.Build();
        try
        {
            return (match.Referee?.Item.Slug ?? "default", settings.Cycles, [.. Enumerable.Range(0, match.TeamCount).Select(match.TeamLabel)]);
        }
        finally
        {
            MatchLoop.StopStrategies(match);
        }
    }

    private static (string Item, int Cycles) Length(LiveBoard board)
    {
        var (item, cycles, _) = Played(board);
        return (item, cycles);
    }

    [Fact]
    public void StartPlaysTheChosenItemLengthAndStrategiesAtOnce()
    {
        var (board, counter) = Board();
        Assert.Equal(("ball-grab", 6000), Length(board));

        var reply = Send(board, counter, "start", ("item", "polo-1v1"), ("minutes", "1"), ("team0", "alpha/"), ("team1", "idle"));
        Assert.Equal(200, reply.Status);
        Assert.Equal($"compiling {Path.Combine(Folder, "alpha")} (1 file)...\n", reply.Text.Split('\n')[0] + "\n");
        Assert.Equal((1, 0), (counter.Starts, counter.Restarts));
        var (item, cycles, teams) = Played(board);
        Assert.Equal(("polo-1v1", 600), (item, cycles));
        Assert.Equal(["alpha-1 [alpha]", "idle"], teams);

        // A length in cycles, a .cs file and the item's demo; the item by its Chinese name, as --item takes it.
        reply = Send(board, counter, "start", ("item", ItemRegistry.Find("ball-grab")!.ChineseName), ("cycles", "40"), ("team0", "beta.cs"), ("team1", "demo"));
        Assert.Equal(200, reply.Status);
        Assert.StartsWith($"compiling {Path.Combine(Folder, "beta.cs")} (1 file)...\n", reply.Text, StringComparison.Ordinal);
        (item, cycles, teams) = Played(board);
        Assert.Equal(("ball-grab", 40), (item, cycles));
        Assert.Equal(["beta [beta.cs]", "ball-grab demo"], teams);
    }

    [Theory]
    [InlineData("item", "nosuch", "start: item \"nosuch\" is not an item of the board (default, ")]
    [InlineData("minutes", "7", "start: minutes must be 10, 5, 3 or 1, got \"7\"")]
    [InlineData("cycles", "-3", "start: cycles must be an integer 0..2147483647, got \"-3\"")]
    [InlineData("cycles", "1e3", "start: cycles must be an integer 0..2147483647, got \"1e3\"")]
    [InlineData("team0", "gamma/", "start: team0: \"gamma/\" is not a strategy of ")]
    [InlineData("team0", "../alpha/", "start: team0: \"../alpha/\" is not a strategy of ")]
    [InlineData("team0", "fixed", "start: team0: \"fixed\" is not a strategy of ")]
    [InlineData("team2", "idle", "start: team2: ball-grab has no team 2 (teams 0 to 1)")]
    [InlineData("seed", "3", "start: unknown parameter \"seed\" (item, minutes, cycles, team0 … team3)")]
    public void ABadChoiceIsOneLineAndChangesNothing(string key, string value, string expected)
    {
        var (board, counter) = Board("--cycles", "30");
        var reply = Send(board, counter, "start", (key, value));
        Assert.Equal(400, reply.Status);
        Assert.StartsWith(expected, reply.Text, StringComparison.Ordinal);
        Assert.Single(reply.Text.TrimEnd('\n').Split('\n'));
        Assert.Equal(0, counter.Starts);
        Assert.Equal(("ball-grab", 30), Length(board));
    }

    [Fact]
    public void BothLengthsOrTheDemoOfASceneThatIsNoItemAreRefused()
    {
        var (board, counter) = Board();
        Assert.Equal("start: minutes and cycles both set the length; give one\n", Send(board, counter, "start", ("minutes", "1"), ("cycles", "5")).Text);
        Assert.Equal("start: team1: demo is the demo strategy of a competition item, and default is not one\n", Send(board, counter, "start", ("item", "default"), ("team1", "demo")).Text);
        Assert.Equal("recompile: unknown parameter \"item\" (recompile plays the current choice again)\n", Send(board, counter, "recompile", ("item", "default")).Text);
        Assert.Equal(0, counter.Starts + counter.Restarts);
        Assert.Null(board.Control("pause", Query(("action", "pause")), counter.Start, counter.Restart)); // the player's own
    }

    [Fact]
    public void RestartReplaysTheLoadedStrategiesAndRecompileLoadsTheEditedSource()
    {
        var (board, counter) = Board("--cycles", "20");
        Assert.Equal(200, Send(board, counter, "start", ("item", "default"), ("cycles", "20"), ("team0", "alpha/"), ("team1", "beta.cs")).Status);
        Assert.Equal(["alpha-1 [alpha]", "beta [beta.cs]"], Played(board).Teams);

        File.WriteAllText(Path.Combine(Folder, "alpha", "Strategy.cs"), Named("alpha-2"));
        Assert.Equal(["alpha-1 [alpha]", "beta [beta.cs]"], Played(board).Teams); // a restart: the strategies as loaded

        var reply = Send(board, counter, "recompile");
        Assert.Equal((200, 1, 1), (reply.Status, counter.Starts, counter.Restarts));
        Assert.StartsWith($"compiling {Path.Combine(Folder, "alpha")} (1 file)...\ncompiled {Path.Combine(Folder, "alpha")} in ", reply.Text, StringComparison.Ordinal);
        var (item, cycles, teams) = Played(board);
        Assert.Equal(("default", 20), (item, cycles));
        Assert.Equal(["alpha-2 [alpha]", "beta [beta.cs]"], teams);

        // A source that no longer compiles: the lines run --strategy prints, and the match plays on as it was.
        File.WriteAllText(Path.Combine(Folder, "alpha", "Strategy.cs"), Named("alpha-3").Replace("new Decision(10, 7)", "new Decision(10, 7", StringComparison.Ordinal));
        reply = Send(board, counter, "recompile");
        Assert.Equal(400, reply.Status);
        var cli = CliRun.Of(string.Empty, "run", "--item", "default", "--cycles", "1", "--strategy", "0=" + Path.Combine(Folder, "alpha"));
        Assert.Equal(2, cli.ExitCode);
        var expected = cli.Stderr.Split('\n').Where(l => !l.StartsWith("compil", StringComparison.Ordinal)).ToArray();
        Assert.StartsWith("--strategy 0: cannot compile ", expected[0], StringComparison.Ordinal);
        string[] lines = reply.Text.Split('\n');
        Assert.Equal(expected[0].Replace("--strategy 0: ", "team 0 (alpha/): ", StringComparison.Ordinal), lines[0]);
        Assert.Equal(expected[1..], lines[1..]);
        Assert.Equal(1, counter.Restarts);
        Assert.Equal(["alpha-2 [alpha]", "beta [beta.cs]"], Played(board).Teams);
    }

    [Fact]
    public void TheCommandLinesStrategyIsTheFirstChoiceAndItsTeamMayChooseItAgain()
    {
        string outside = Path.Combine(Folder, "alpha", "Strategy.cs"); // a spec as --strategy takes it, not a name of the board
        var (board, counter) = Board("--item", "default", "--cycles", "10", "--strategy", "1=" + outside);
        Assert.Equal(["chase-ball", "alpha-1 [Strategy.cs]"], Played(board).Teams);
        var json = System.Text.Json.JsonDocument.Parse(board.Json()).RootElement;
        Assert.Equal([null, outside, null, null], json.GetProperty("commandLine").EnumerateArray().Select(e => e.GetString()));
        Assert.Equal(["scene", outside], json.GetProperty("current").GetProperty("teams").EnumerateArray().Select(e => e.GetString()));

        Assert.Equal(400, Send(board, counter, "start", ("team0", outside)).Status); // another team's command-line spec is not offered to team 0
        Assert.Equal(204, Send(board, counter, "start", ("item", "default"), ("team0", "idle"), ("team1", outside)).Status);
        Assert.Equal(["idle", "alpha-1 [Strategy.cs]"], Played(board).Teams);
    }

    [Fact]
    public void TheFolderOffersItsSourcesFoldersAndAssemblies()
    {
        File.WriteAllBytes(Path.Combine(Folder, "Gamma.dll"), [0]);
        Directory.CreateDirectory(Path.Combine(Folder, "delta"));
        File.WriteAllBytes(Path.Combine(Folder, "delta", "Delta.dll"), [0]);
        Directory.CreateDirectory(Path.Combine(Folder, "empty"));
        Directory.CreateDirectory(Path.Combine(Folder, ".hidden"));
        File.WriteAllText(Path.Combine(Folder, ".hidden", "X.cs"), "class X {}");
        Directory.CreateDirectory(Path.Combine(Folder, "obj"));
        File.WriteAllText(Path.Combine(Folder, "obj", "Y.cs"), "class Y {}");
        File.WriteAllText(Path.Combine(Folder, "notes.txt"), "-");
        Assert.Equal(["Gamma.dll", "alpha/", "beta.cs", "delta/Delta.dll"], StrategyCatalog.Scan(Folder));
        Assert.Equal(Path.Combine(Folder, "delta", "Delta.dll"), StrategyCatalog.Spec(Folder, "delta/Delta.dll"));
        Assert.Empty(StrategyCatalog.Scan(Path.Combine(Folder, "no-such-folder")));

        // An assembly that is no strategy is refused at start as the command line refuses it.
        var (board, counter) = Board();
        var reply = Send(board, counter, "start", ("team0", "Gamma.dll"));
        Assert.Equal(400, reply.Status);
        Assert.StartsWith($"team 0 (Gamma.dll): cannot load strategy assembly {Path.Combine(Folder, "Gamma.dll")}: ", reply.Text, StringComparison.Ordinal);
    }

    [Fact]
    public void StrategiesBelongToLiveAndNeedAFolder()
    {
        var alone = CliRun.Of(string.Empty, "run", "--strategies", Folder);
        Assert.Equal((2, string.Empty), (alone.ExitCode, alone.Stdout));
        Assert.StartsWith($"run: --strategies \"{Folder}\" belongs to --live (the control board of the live view). Usage: ", alone.Stderr, StringComparison.Ordinal);
        Assert.Single(alone.Stderr.TrimEnd('\n').Split('\n'));

        string missing = Path.Combine(Folder, "no-such");
        var none = CliRun.Of(string.Empty, "run", "--live", "--strategies", missing);
        Assert.Equal((2, string.Empty), (none.ExitCode, none.Stdout));
        Assert.Equal($"run: --strategies \"{missing}\": no such folder\n", none.Stderr);
    }

    private sealed class Counter
    {
        public int Starts { get; private set; }

        public int Restarts { get; private set; }

        public void Start() => Starts++;

        public void Restart() => Restarts++;
    }
}
