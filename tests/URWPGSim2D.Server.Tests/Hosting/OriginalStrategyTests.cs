using System.Reflection;
using System.Runtime.Loader;
using URWPGSim2D.Compat.Adapter;
using URWPGSim2D.Engine.Matches;

namespace URWPGSim2D.Server.Tests.Hosting;

/// <summary>
/// Strategies in the original's style (tests/…/Hosting/Original, written for this repository),
/// compiled from source and from a DLL and played for a few hundred cycles.
/// </summary>
public sealed class OriginalStrategyTests
{
    private const string OneFishOneBall =
        """{"noise":false,"fish":[{"team":0,"position":[-600,0]},{"team":1,"position":[1300,900],"heading":3.14159,"strategy":"idle"}],"balls":[{"position":[-200,100]}]}""";

    internal static string Folder(string name) => Path.Combine(AppContext.BaseDirectory, "Hosting", "Original", name);

    /// <summary>The strategy object a team wrote (inside the adapter), to read what it recorded.</summary>
    internal static object Inner(IStrategy strategy) => Assert.IsType<OriginalStrategyAdapter>(strategy).Strategy;

    internal static T Field<T>(object o, string name) =>
        (T)(o.GetType().GetField(name, BindingFlags.Public | BindingFlags.Instance | BindingFlags.Static)
            ?? throw new InvalidOperationException($"no field {name}")).GetValue(o)!;

    private static Match Play(string json, IStrategy strategy, int cycles, ManualStrategyClock? clock = null, int timeoutMs = MatchBuilder.DefaultStrategyTimeoutMs)
    {
        var teams = new TeamStrategy?[] { new("test", strategy, Isolated: true, clock ?? new ManualStrategyClock()), null };
        var match = TestMatches.FromJson(json, teams, timeoutMs);
        match.Play(cycles);
        match.Teams.Stop();
        return match;
    }

    [Fact]
    public void ADribblingStrategyCompiledFromSourcePushesTheBallTowardTheGoal()
    {
        IStrategy strategy = StrategyResolver.Load(Folder("Dribbler"));
        Assert.Equal("Dribbler", strategy.TeamName);
        var match = Play(OneFishOneBall, strategy, 300);
        Assert.Equal(0, match.Caller().TotalFaults);
        Assert.Equal(300, Field<int>(Inner(strategy), "Calls"));
        Assert.True(match.World.Balls[0].Position.X > 200f, $"ball pushed toward +X, at {match.World.Balls[0].Position}");
    }

    [Fact]
    public void TheSameStrategyFromADllPlaysTheSameMatch()
    {
        string dir = Path.Combine(Path.GetTempPath(), "urwpg-dribbler-" + Guid.NewGuid().ToString("N"));
        Directory.CreateDirectory(dir);
        try
        {
            string dll = Path.Combine(dir, "TeamDribbler.dll");
            File.WriteAllBytes(dll, StrategyCompiler.Compile("TeamDribbler", StrategyCompiler.SourceFiles(Folder("Dribbler"))));
            var fromDll = Play(OneFishOneBall, StrategyResolver.Load(dll), 300);
            var fromSource = Play(OneFishOneBall, StrategyResolver.Load(Folder("Dribbler")), 300);
            Assert.Equal(fromSource.World.Balls[0].Position, fromDll.World.Balls[0].Position);
            Assert.Equal(fromSource.World.Fish[0].Position, fromDll.World.Fish[0].Position);
        }
        finally
        {
            Directory.Delete(dir, recursive: true);
        }
    }

    [Fact]
    public void EachTeamGetsItsOwnCollectibleLoadContextSharingTheCompatibilityAssembly()
    {
        IStrategy a = StrategyResolver.Load(Folder("Dribbler"));
        IStrategy b = StrategyResolver.Load(Folder("Dribbler"));
        var ca = AssemblyLoadContext.GetLoadContext(Inner(a).GetType().Assembly)!;
        var cb = AssemblyLoadContext.GetLoadContext(Inner(b).GetType().Assembly)!;
        Assert.NotSame(ca, cb);
        Assert.True(ca.IsCollectible);
        Assert.IsType<StrategyLoadContext>(ca);
        Assert.Same(typeof(Common.Mission).Assembly, Inner(a).GetType().GetMethod("GetDecision")!.GetParameters()[0].ParameterType.Assembly);
    }

    [Fact]
    public void AStrategySeesItemVariablesObstaclesAndHeadTips()
    {
        IStrategy strategy = StrategyResolver.Load(Folder("Observer"));
        const string json = """
            {"noise":false,"fish":[{"team":0,"position":[-600,0],"decision":{"vcode":8,"tcode":9}},{"team":0,"position":[-600,400]},{"team":1,"position":[600,0],"heading":3.14159,"strategy":"idle"}],
             "balls":[{"position":[0,0]}],
             "obstacles":[{"type":"rectangle","center":[300,-500],"length":200,"width":100,"heading":0.5},{"type":"round","center":[-300,600],"radius":70}]}
            """;
        var teams = new TeamStrategy?[] { new("observer", strategy, Isolated: true, new ManualStrategyClock()), null };
        var match = TestMatches.FromJson(json, teams);
        var variables = new Dictionary<string, string> { ["Ball_0_Left_Status"] = "1", ["Ball_0_Right_Status"] = "0" };
        match.Snapshot.SetItem("抢球博弈", variables, 6000);
        match.Play(200);
        match.Teams.Stop();

        object s = Inner(strategy);
        Assert.Equal(0, match.Caller().TotalFaults);
        Assert.Equal(200, Field<int>(s, "Calls"));
        Assert.Equal(2, Field<int>(s, "VariableCount"));
        Assert.Equal("left=1;right=0;", Field<string>(s, "VariableText"));
        Assert.Equal(1, Field<int>(s, "RectCount"));
        Assert.Equal(1, Field<int>(s, "RoundCount"));
        Assert.Equal(300f, Field<float>(s, "FirstRectX"));
        Assert.Equal(-500f, Field<float>(s, "FirstRectZ"));
        Assert.Equal(70f, Field<float>(s, "FirstRoundRadius"));
        Assert.Equal(110f, Field<float>(s, "HeadAhead"), 0.01f); // L/2 + H = 80 + 30 ahead of the body centre
        Assert.True(Field<float>(s, "MaxHeadError") < 1e-4f, "the head tip lies straight ahead of every fish");
        Assert.Equal(6000 - 199, Field<int>(s, "RemainingCycles"));
        Assert.Equal("抢球博弈", Field<string>(s, "ItemName"));
        Assert.Equal(307f, Field<float>(s, "TableV14"));
        Assert.Equal(Common.HalfCourt.LEFT, Field<Common.HalfCourt>(s, "MyHalf"));
        Assert.Equal(0, Field<int>(s, "LastTeamId"));
        Assert.Equal(new Decision(5, 7), match.World.Fish[0].Decision);
        Assert.Equal(new Decision(5, 7), match.World.Fish[1].Decision);
    }

    [Fact]
    public void AtHalfTimeTeamsRefIsReversedAndTheStrategyGetsItsNewTeamId()
    {
        IStrategy strategy = StrategyResolver.Load(Folder("Observer"));
        var teams = new TeamStrategy?[] { new("observer", strategy, Isolated: true, new ManualStrategyClock()), null };
        var match = TestMatches.FromJson(OneFishOneBall, teams);
        match.Play(5);
        object s = Inner(strategy);
        Assert.Equal(0, Field<int>(s, "LastTeamId"));
        Assert.Equal(new Decision(5, 7), match.World.Fish[0].Decision);

        match.Snapshot.SetSidesSwapped(true);
        match.Play(5);
        match.Teams.Stop();
        Assert.Equal(1, Field<int>(s, "LastTeamId"));
        Assert.Equal(Common.HalfCourt.RIGHT, Field<Common.HalfCourt>(s, "MyHalf"));
        Assert.True(Field<bool>(s, "Exchanged"));
        Assert.Equal(new Decision(6, 7), match.World.Fish[0].Decision); // its answer (VCode 5 + teamId) still drives its own fish
        Assert.Equal(Decision.Stop, match.World.Fish[1].Decision);
    }

    [Fact]
    public void TheMissionIsAFreshDeepCopyEveryCycleAndCodesAreClamped()
    {
        IStrategy strategy = StrategyResolver.Load(Folder("Mutator"));
        var match = Play(OneFishOneBall, strategy, 200);
        object s = Inner(strategy);
        Assert.Equal(200, Field<int>(s, "Calls"));
        Assert.Equal(0, Field<int>(s, "Leaks"));
        Assert.Equal(0, match.Caller().TotalFaults); // five extra decisions are ignored
        Assert.Equal(new Decision(15, 0), match.World.Fish[0].Decision); // V40 T−3 clamped to 0..15
        Assert.Single(match.World.Balls);
    }

    [Fact]
    public void ATeamsOwnStrategyHelperWinsOverTheServersCopy()
    {
        IStrategy strategy = StrategyResolver.Load(Folder("OwnHelper"));
        var match = Play(OneFishOneBall, strategy, 50);
        Assert.Equal(0, match.Caller().TotalFaults);
        Assert.Equal(new Decision(3, 11), match.World.Fish[0].Decision);
        var uses = Inner(strategy).GetType().GetProperty("HelperUses")!.GetValue(Inner(strategy));
        Assert.Equal(50, uses);
    }

    [Fact]
    public void FaultsKeepTheFishOnTheirLastDecisionsAndNeverStopTheMatch()
    {
        IStrategy strategy = StrategyResolver.Load(Folder("Faulty"));
        var clock = new ManualStrategyClock();
        Inner(strategy).GetType().GetField("Hang")!.SetValue(null, (Action)clock.Hang);
        var teams = new TeamStrategy?[] { new("faulty", strategy, Isolated: true, clock), null };
        var match = TestMatches.FromJson(OneFishOneBall, teams);
        var seen = new List<Decision>();
        for (int k = 0; k < 30; k++)
        {
            match.Step();
            seen.Add(match.World.Fish[0].Decision);
        }

        var slot = match.Caller().Slots[0];
        try
        {
            Assert.Equal(30, match.World.Cycle);
            Assert.Equal(new Decision(10, 7), seen[3]);  // cycle 4: a good answer
            Assert.Equal(new Decision(10, 7), seen[8]);  // cycles 5..9 threw
            Assert.Equal(new Decision(10, 7), seen[13]); // cycles 10..14 answered no decisions
            Assert.Equal(new Decision(4, 7), seen[18]);  // cycles 15..19 good again
            Assert.Equal(Decision.Stop, seen[19]);       // hung in cycle 20: given up on, idle from then on
            Assert.Equal(Decision.Stop, seen[29]);
            Assert.Equal(20, slot.IdleFromCycle);
            Assert.Equal(5, slot.Exceptions);
            Assert.Equal(5, slot.BadAnswers);
            Assert.Equal(1, slot.Timeouts);
            Assert.Equal("cycle 5: InvalidOperationException: faulty on purpose", slot.FirstFault);
            string summary = MatchSummary.Format(match, TimeSpan.FromMilliseconds(1));
            Assert.Contains("team 0 (faulty): 5 exceptions, 1 timeouts, 5 bad answers, out of time in cycle 20; its fish kept their last decisions until then and stopped after", summary, StringComparison.Ordinal);
        }
        finally
        {
            clock.Release();
            match.Teams.Stop();
        }
    }

    [Fact]
    public void TooFewDecisionsIsABadAnswerNamingTheCounts()
    {
        IStrategy strategy = StrategyResolver.Load(Folder("Faulty"));
        var match = Play(OneFishOneBall, strategy, 10);
        Assert.Equal("cycle 5: InvalidOperationException: faulty on purpose", match.Caller().Slots[0].FirstFault);
        var adapter = Assert.IsType<OriginalStrategyAdapter>(strategy);
        var e = Assert.Throws<StrategyContractException>(() => adapter.Decide(match.Snapshot, [0], new Decision[1]));
        Assert.Equal("GetDecision returned 0 decisions for 1 fish", e.Message);
    }
}
