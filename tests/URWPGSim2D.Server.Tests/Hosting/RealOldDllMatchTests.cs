using URWPGSim2D.Tests.OldStrategies;

namespace URWPGSim2D.Server.Tests.Hosting;

/// <summary>
/// The real DLLs built for the original (<see cref="RealOldDlls"/>, read from ../shared/olddll) each play a
/// whole match of their item as team 0 against the item's demo, in a strategy host and in the server's
/// process (<c>--isolation none</c>), with no fault, under the team name their code returns; and they steer:
/// a DLL whose decisions are all zero plays exactly the match a source returning all-zero decisions plays, and the others do not.
/// Original-API strategies run in this test process with <c>--isolation none</c>, so these tests run alone
/// (<see cref="InProcessStaticsCollection"/>).
/// </summary>
[Collection(InProcessStaticsCollection.Name)]
public sealed class RealOldDllMatchTests
{
    public static TheoryData<string, string> Runs()
    {
        var data = new TheoryData<string, string>();
        foreach (var dll in RealOldDlls.All())
        {
            data.Add(dll.File, "process");
            data.Add(dll.File, "none");
        }

        return data;
    }

    [Theory]
    [MemberData(nameof(Runs))]
    public void EachRealOldDllPlaysAWholeMatchOfItsItemWithoutAFault(string file, string isolation)
    {
        var dll = RealOldDlls.All().Single(d => d.File == file);
        var run = Play(dll, "0=" + RealOldDlls.PathOf(file), isolation);
        Assert.True(run.ExitCode == 0, run.Stderr);
        Assert.True(run.Stdout.Contains("strategy faults: none\n", StringComparison.Ordinal), run.Stdout);
        Assert.Contains("end: match over", run.Stdout, StringComparison.Ordinal);
        if (dll.TeamName is { } name)
        {
            Assert.Contains($"team 0 ({name} [{file}])", run.Stdout, StringComparison.Ordinal);
        }

        // The same match with team 0 played by a source that returns all-zero decisions: the same contacts
        // and sub-steps exactly when the DLL's decisions are all zero too.
        string folder = Path.Combine(Path.GetTempPath(), "urwpg-zero-" + Guid.NewGuid().ToString("N"));
        Directory.CreateDirectory(folder);
        try
        {
            string zero = Path.Combine(folder, "Zero.cs");
            File.WriteAllText(zero, ZeroDecisions);
            var still = Play(dll, "0=" + zero, "none");
            Assert.True(still.ExitCode == 0, still.Stderr);
            string Contacts(CliRun r) => Line(r.Stdout, "contacts:") + "\n" + Line(r.Stdout, "sub-steps:");
            if (dll.Idle)
            {
                Assert.Equal(Contacts(still), Contacts(run));
            }
            else
            {
                Assert.NotEqual(Contacts(still), Contacts(run));
            }
        }
        finally
        {
            Directory.Delete(folder, recursive: true);
        }
    }

    private const string ZeroDecisions = """
        using URWPGSim2D.Common;
        using URWPGSim2D.StrategyLoader;

        namespace URWPGSim2D.Strategy
        {
            public class Strategy : System.MarshalByRefObject, IStrategy
            {
                private Decision[] decisions;

                public string GetTeamName() { return "zero"; }

                public Decision[] GetDecision(Mission mission, int teamId)
                {
                    if (decisions == null) { decisions = new Decision[mission.CommonPara.FishCntPerTeam]; }
                    return decisions;
                }
            }
        }
        """;

    [Fact]
    public void AnEntryPlayedInAnItemItWasNotWrittenForFaultsAndTheMatchCompletes()
    {
        // The push-ball-via-channel entry filed under the double-fish race reads a second fish of its team and
        // a ball there: each call throws, each is charged to its team, and the race is played to its end.
        var run = CliRun.Of(string.Empty, "run", "--item", "double-fish-race-via-holes", "--minutes", "1", "--strategy", "0=" + RealOldDlls.PathOf(RealOldDlls.Known[2].File), "--strategy-timeout", "2000");
        Assert.True(run.ExitCode == 0, run.Stderr);
        Assert.Contains("end: match over", run.Stdout, StringComparison.Ordinal);
        string faults = run.Stdout[run.Stdout.IndexOf("strategy faults:", StringComparison.Ordinal)..];
        int cycles = int.Parse(run.Stdout[7..run.Stdout.IndexOf(" cycles", StringComparison.Ordinal)], System.Globalization.CultureInfo.InvariantCulture);
        Assert.Contains($"{cycles} exceptions, 0 timeouts, 0 bad answers", faults, StringComparison.Ordinal);
        Assert.Contains("ArgumentOutOfRangeException", faults, StringComparison.Ordinal);
    }

    // Ball-grab entries are played for ten minutes (one of them acts only in the first 30 s of a ten-minute
    // match, as it reads RemainingCycles); the others for one minute, a whole match of their item too.
    // The deadline is generous (2 s of CPU a call, against the default 100 ms): what is checked is that the DLL
    // never throws or answers badly, not how fast a loaded test machine runs it.
    private static CliRun Play(RealOldDll dll, string strategy, string isolation) =>
        CliRun.Of(string.Empty, "run", "--item", dll.Item, "--minutes", dll.Item == "ball-grab" ? "10" : "1", "--strategy", strategy, "--isolation", isolation, "--strategy-timeout", "2000");

    private static string Line(string stdout, string start) =>
        stdout.Split('\n').Single(l => l.StartsWith(start, StringComparison.Ordinal));
}
