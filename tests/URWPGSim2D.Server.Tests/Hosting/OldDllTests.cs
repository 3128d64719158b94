using Microsoft.CodeAnalysis;
using URWPGSim2D.Engine.Matches;
using URWPGSim2D.Server.Tests.Items;
using URWPGSim2D.Tests.OldStrategies;

namespace URWPGSim2D.Server.Tests.Hosting;

/// <summary>
/// <c>run --strategy TEAM=old.dll</c> with DLLs in the shape of those built for the original (x86,
/// mscorlib 2.0, the original's assembly names; compiled here by <see cref="OldStrategyCompiler"/>):
/// they play every item, exactly as the same source compiled for this server does, and fault like any
/// other strategy; a DLL holding native code is refused in one line. The matches play original-API
/// strategies in this test process, so these tests run alone (<see cref="InProcessStaticsCollection"/>).
/// </summary>
[Collection(InProcessStaticsCollection.Name)]
public sealed class OldDllTests() : TempFolderTest("urwpg-old-dll-")
{
    private const string OneFishOneBall =
        """{"noise":false,"fish":[{"team":0,"position":[-600,0]},{"team":1,"position":[1300,900],"heading":3.14159,"strategy":"idle"}],"balls":[{"position":[-200,100]}]}""";

    private static readonly Lazy<byte[]> Dribbler = new(() => OldStrategyCompiler.Compile("OldDribbler", Platform.X86, OldStrategySources.Dribbler));

    [Fact]
    public void AnOldDllPlaysTheSameMatchAsItsSourceCompiledForThisServer()
    {
        string dll = Write("OldDribbler.dll", Dribbler.Value);
        string source = Path.Combine(Folder, "Dribbler.cs");
        File.WriteAllText(source, OldStrategySources.Dribbler);
        IStrategy old = StrategyResolver.Load(dll);
        Assert.Equal("Old dribbler", old.TeamName);
        var fromDll = Play(old);
        var fromSource = Play(StrategyResolver.Load(source));
        Assert.Equal(0, fromDll.Caller().TotalFaults);
        Assert.Equal(300, OriginalStrategyTests.Field<int>(OriginalStrategyTests.Inner(old), "Calls"));
        Assert.True(fromDll.World.Balls[0].Position.X > 200f, $"ball pushed toward +X, at {fromDll.World.Balls[0].Position}");
        Assert.Equal(fromSource.World.Balls[0].Position, fromDll.World.Balls[0].Position);
        Assert.Equal(fromSource.World.Fish[0].Position, fromDll.World.Fish[0].Position);
    }

    [Theory]
    [MemberData(nameof(ItemMatches.Slugs), MemberType = typeof(ItemMatches))]
    public void AnOldDllPlaysEveryItemForEveryTeamWithoutAFault(string item)
    {
        string dll = Write("OldDribbler.dll", Dribbler.Value);
        var competition = ItemRegistry.Find(item)!;
        var teams = new TeamStrategy?[Math.Max(2, competition.TeamCount)];
        for (int t = 0; t < competition.TeamCount; t++)
        {
            teams[t] = new TeamStrategy("old.dll", StrategyResolver.Load(dll), Isolated: true, new ManualStrategyClock());
        }

        var match = MatchBuilder.Build(competition.CreateScenario(1), teams, seed: 1, cycles: 60);
        for (int k = 0; k < 60 && !match.IsOver; k++)
        {
            match.Step();
        }

        match.Teams.Stop();
        Assert.Equal(0, match.Caller().TotalFaults);
        Assert.True(match.World.Cycle > 0);
    }

    [Theory]
    [InlineData("new-ball-grab", "CompetitionPeriod=0;")]
    [InlineData("relay-with-ball", "FinishedSingleTripCount=1;")]
    [InlineData("push-ball-via-channel", "IsCollidedBallAndFish0AtStage1=no;IsCollidedBallAndFish1AtStage1=no;IsCollidedBallAndFish0AtStage2=no;IsCollidedBallAndFish1AtStage2=no;IsCollidedBallAndFish0AtStage3=no;IsCollidedBallAndFish1AtStage3=no;IsCollidedBallAndFish0AtStage4=no;IsCollidedBallAndFish1AtStage4=no;ExecutingTaskNo=2;")]
    public void AnOldDllReadsTheOlderItemsVariablesAsItsEntriesDid(string item, string seen)
    {
        string dll = Write("OldReader.dll", OldStrategyCompiler.Compile("OldReader", Platform.X86, OldStrategySources.VariableReader));
        var competition = ItemRegistry.Find(item)!;
        IStrategy old = StrategyResolver.Load(dll);
        var teams = new TeamStrategy?[] { new("old.dll", old, Isolated: true, new ManualStrategyClock()), null };

        // The ball where it ends relay leg 1 (right pocket) and the channel item's first stage (past x 600).
        var scenario = competition.CreateScenario(1);
        scenario = scenario with { Balls = [scenario.Balls[0] with { Position = item == "new-ball-grab" ? scenario.Balls[0].Position : new System.Numerics.Vector2(400f, 0f) }, .. scenario.Balls.Skip(1)] };
        var match = MatchBuilder.Build(scenario, teams, seed: 1, cycles: 20);
        match.Play(5);
        match.Teams.Stop();
        Assert.Equal(0, match.Caller().TotalFaults);
        Assert.Equal(seen, OriginalStrategyTests.Field<string>(OriginalStrategyTests.Inner(old), "Seen"));
    }

    [Fact]
    public void RunPlaysAnOldDllForEachTeam()
    {
        string dll = Write("OldDribbler.dll", Dribbler.Value);
        var run = CliRun.Of(string.Empty, "run", "--item", "ball-grab", "--cycles", "40", "--strategy", "0=" + dll, "--strategy", "1=" + dll);
        Assert.True(run.ExitCode == 0, run.Stderr);
        Assert.True(run.Stdout.Contains("score: team 0 (Old dribbler [OldDribbler.dll]) 0, team 1 (Old dribbler [OldDribbler.dll]) 0\n", StringComparison.Ordinal), run.Stdout);
        Assert.True(run.Stdout.Contains("strategy faults: none\n", StringComparison.Ordinal), run.Stdout);
    }

    [Theory]
    [InlineData("process")]
    [InlineData("none")]
    public void AnOldDllWritesAndReadsFilesInItsWorkingDirectory(string isolation)
    {
        // Appends a line a cycle to a file named relatively and reads it back: an exception (a fault) if the
        // file does not hold every line written so far. In a host the working directory is its scratch folder.
        const string Notes = """
            using URWPGSim2D.Common;
            using URWPGSim2D.StrategyLoader;
            namespace URWPGSim2D.Strategy
            {
                public class Strategy : System.MarshalByRefObject, IStrategy
                {
                    private Decision[] decisions;
                    private string written = "";
                    public string GetTeamName() { return "Note taker"; }
                    public Decision[] GetDecision(Mission mission, int teamId)
                    {
                        if (decisions == null) { decisions = new Decision[mission.CommonPara.FishCntPerTeam]; }
                        System.IO.File.AppendAllText("notes.txt", "x");
                        written = written + "x";
                        if (System.IO.File.ReadAllText("notes.txt") != written) { throw new System.InvalidOperationException("notes lost"); }
                        return decisions;
                    }
                }
            }
            """;
        string dll = Write("OldNotes.dll", OldStrategyCompiler.Compile("OldNotes", Platform.X86, Notes));
        string before = Environment.CurrentDirectory;
        Environment.CurrentDirectory = Folder;
        try
        {
            var run = CliRun.Of(string.Empty, "run", "--cycles", "30", "--strategy", "0=" + dll, "--isolation", isolation);
            Assert.True(run.ExitCode == 0, run.Stderr);
            Assert.True(run.Stdout.Contains("strategy faults: none\n", StringComparison.Ordinal), run.Stdout);
            Assert.Equal(isolation == "none", File.Exists(Path.Combine(Folder, "notes.txt")));
        }
        finally
        {
            Environment.CurrentDirectory = before;
        }
    }

    [Fact]
    public void AnOldDllsFaultsAreCountedLikeAnyStrategys()
    {
        string dll = Write("OldFaulty.dll", OldStrategyCompiler.Compile("OldFaulty", Platform.X86, OldStrategySources.Faulty));
        var run = CliRun.Of(string.Empty, "run", "--cycles", "25", "--strategy", "0=" + dll);
        Assert.Equal(0, run.ExitCode);
        const string Line = "  team 0 (Old faulty [OldFaulty.dll]): 15 exceptions, 0 timeouts, 0 bad answers; its fish kept their last decisions; first: cycle 11: InvalidOperationException: broken after ten cycles\n";
        Assert.True(run.Stdout.Contains(Line, StringComparison.Ordinal), run.Stdout);
    }

    [Fact]
    public void AnOldDllHoldingNativeCodeIsRefusedInOneLineWithExitTwo()
    {
        byte[] image = (byte[])Dribbler.Value.Clone();
        using (var pe = new System.Reflection.PortableExecutable.PEReader(System.Collections.Immutable.ImmutableArray.Create(image)))
        {
            Assert.True(pe.PEHeaders.TryGetDirectoryOffset(pe.PEHeaders.PEHeader!.CorHeaderTableDirectory, out int header));
            image[header + 16] &= 0xFE; // the CLR header's ILONLY flag
        }

        AssertRefusedAsDocumented(image);
    }

    [Fact]
    public void AnOldDllUsingApiTheCompatibilityAssemblyLacksIsRefusedNamingIt()
    {
        const string UsesVector4 = "namespace Uses { public class Vectors { public object Make() { return Microsoft.Xna.Framework.Vector4.One; } } }";
        AssertRefusedAsDocumented(OldStrategyCompiler.CompileWithXnaVector4("OldVector4", OldStrategySources.Dribbler, UsesVector4));
    }

    [Fact]
    public void AnOldDllUsingWhatThisRuntimeLacksIsRefusedNamingIt()
    {
        const string ShowsABox = "namespace Uses { public class Boxes { public int Show() { return System.Windows.Forms.MessageBox.Show(\"hello\"); } } }";
        AssertRefusedAsDocumented(OldStrategyCompiler.CompileWithWindowsForms("OldBoxes", OldStrategySources.Dribbler, ShowsABox));
    }

    // Runs the image as teams/red/Strategy.dll: exit 2, nothing written, one line of stderr that
    // docs/strategies.md shows in a code block of its own.
    private void AssertRefusedAsDocumented(byte[] image)
    {
        string red = Path.Combine(Folder, "teams", "red");
        Directory.CreateDirectory(red);
        string dll = Path.Combine(red, "Strategy.dll");
        File.WriteAllBytes(dll, image);
        string trace = Path.Combine(Folder, "t.jsonl");
        var run = CliRun.Of(string.Empty, "run", "--cycles", "5", "--strategy", "0=" + dll, "--trace", trace);
        Assert.Equal(2, run.ExitCode);
        Assert.Equal(string.Empty, run.Stdout);
        Assert.False(File.Exists(trace));
        string line = run.Stderr.Replace(Folder + Path.DirectorySeparatorChar, string.Empty, StringComparison.Ordinal);
        Assert.EndsWith("\n", line, StringComparison.Ordinal);
        Assert.DoesNotContain('\n', line.TrimEnd('\n'));
        string docs = File.ReadAllText(Docs.Repository.PathOf("docs/strategies.md")).Replace("\r\n", "\n", StringComparison.Ordinal);
        Assert.Contains("```\n" + line + "```\n", docs, StringComparison.Ordinal);
    }

    private static Match Play(IStrategy strategy)
    {
        var teams = new TeamStrategy?[] { new("test", strategy, Isolated: true, new ManualStrategyClock()), null };
        var match = URWPGSim2D.Server.Tests.Simulation.TestMatches.FromJson(OneFishOneBall, teams);
        match.Play(300);
        match.Teams.Stop();
        return match;
    }

    private string Write(string name, byte[] image)
    {
        string path = Path.Combine(Folder, name);
        File.WriteAllBytes(path, image);
        return path;
    }
}
