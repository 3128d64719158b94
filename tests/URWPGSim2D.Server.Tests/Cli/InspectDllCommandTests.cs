using URWPGSim2D.Tests.OldStrategies;

namespace URWPGSim2D.Server.Tests.Cli;

/// <summary>
/// <c>inspect-dll FILE</c> on the real DLLs built for the original (<see cref="RealOldDlls"/>) and on DLLs
/// in their shape compiled here: what each is, whether it will load, the missing members listed (exit 2),
/// and one line with exit 2 for a file that is not an assembly. docs/strategies.md shows its real output.
/// </summary>
[Collection(InProcessStaticsCollection.Name)]
public sealed class InspectDllCommandTests() : TempFolderTest("urwpg-inspect-")
{
    public static TheoryData<string> Known() => new(RealOldDlls.Known.Select(d => d.File));

    [Theory]
    [MemberData(nameof(Known))]
    public void EachRealOldDllIsDescribedAndWillLoad(string file)
    {
        var dll = RealOldDlls.Known.Single(d => d.File == file);
        var run = CliRun.Of(string.Empty, "inspect-dll", RealOldDlls.PathOf(file));
        Assert.True(run.ExitCode == 0, run.Stdout + run.Stderr);
        Assert.Equal(string.Empty, run.Stderr);
        string[] lines = run.Stdout.Split('\n');
        Assert.Contains("framework: .NET Framework 2.0-3.5 (runtime v2.0.50727)", lines);
        Assert.Contains("strategy API: the original's (URWPGSim2D.StrategyLoader.IStrategy)", lines);
        Assert.Contains("built for the original: yes (retargeted to the compatibility assembly when it loads)", lines);
        Assert.Contains("strategy class: URWPGSim2D.Strategy.Strategy", lines);
        Assert.Contains("team name: " + dll.TeamName, lines);
        Assert.Contains("  mscorlib 2.0.0.0: this runtime's mscorlib", lines);
        Assert.Contains("  URWPGSim2D.StrategyLoader 1.2.123.20110: the compatibility assembly (URWPGSim2D.Compat)", lines);
        Assert.Contains("sha-256: " + Convert.ToHexStringLower(System.Security.Cryptography.SHA256.HashData(File.ReadAllBytes(RealOldDlls.PathOf(file)))), lines);
        Assert.Equal("loads: yes", lines[^2]);
    }

    [Fact]
    public void TheItemAnEntryWasWrittenForIsFoundFromTheMissionVariablesItReads()
    {
        var run = CliRun.Of(string.Empty, "inspect-dll", RealOldDlls.PathOf(RealOldDlls.Known[2].File));
        Assert.Contains("items its code mentions: push-ball-via-channel (reads IsCollidedBallAndFish0AtStage1, IsCollidedBallAndFish1AtStage1, IsCollidedBallAndFish1AtStage2 and 1 more)\n", run.Stdout, StringComparison.Ordinal);
        Assert.Contains("architecture: any CPU\n", run.Stdout, StringComparison.Ordinal);
    }

    [Fact]
    public void TheOutputDocsStrategiesShowsIsRealOutput()
    {
        string copy = Path.Combine(Folder, "StrategyRainbow2V2.dll");
        File.Copy(RealOldDlls.PathOf("ball-grab-StrategyRainbow2V2.dll"), copy);
        var run = CliRun.Of(string.Empty, "inspect-dll", copy);
        Assert.Equal(0, run.ExitCode);
        string shown = run.Stdout.Replace(Folder + Path.DirectorySeparatorChar, string.Empty, StringComparison.Ordinal);
        string docs = File.ReadAllText(Docs.Repository.PathOf("docs/strategies.md")).Replace("\r\n", "\n", StringComparison.Ordinal);
        Assert.Contains("```\n" + shown + "```\n", docs, StringComparison.Ordinal);
    }

    [Fact]
    public void ADllUsingWhatThisRuntimeLacksIsListedWholeWithExitTwo()
    {
        const string ShowsABox = "namespace Uses { public class Boxes { public int Show() { return System.Windows.Forms.MessageBox.Show(\"hello\"); } } }";
        string dll = Path.Combine(Folder, "Boxes.dll");
        File.WriteAllBytes(dll, OldStrategyCompiler.CompileWithWindowsForms("Boxes", OldStrategySources.Dribbler, ShowsABox));
        var run = CliRun.Of(string.Empty, "inspect-dll", dll);
        Assert.Equal(2, run.ExitCode);
        Assert.Equal(string.Empty, run.Stderr);
        Assert.Contains("  System.Windows.Forms 2.0.0.0: not found\n", run.Stdout, StringComparison.Ordinal);
        Assert.EndsWith(
            "loads: no: it uses parts of .NET Framework that this runtime does not have: System.Windows.Forms.MessageBox, System.Windows.Forms.MessageBox.Show\n"
            + "missing:\n  System.Windows.Forms.MessageBox (System.Windows.Forms)\n  System.Windows.Forms.MessageBox.Show (System.Windows.Forms)\n",
            run.Stdout,
            StringComparison.Ordinal);
    }

    [Fact]
    public void AFileThatIsNotAnAssemblyIsOneLineWithExitTwo()
    {
        string text = Path.Combine(Folder, "notes.dll");
        File.WriteAllText(text, "not a DLL");
        var run = CliRun.Of(string.Empty, "inspect-dll", text);
        Assert.Equal(2, run.ExitCode);
        Assert.Equal(string.Empty, run.Stdout);
        Assert.StartsWith($"inspect-dll: {text}: not a .NET assembly", run.Stderr, StringComparison.Ordinal);
        Assert.Single(run.Stderr.TrimEnd('\n').Split('\n'));

        var missing = CliRun.Of(string.Empty, "inspect-dll", Path.Combine(Folder, "absent.dll"));
        Assert.Equal(2, missing.ExitCode);
        Assert.Equal($"inspect-dll: {Path.Combine(Folder, "absent.dll")}: no such file\n", missing.Stderr);
    }

    [Fact]
    public void NoFileOrTwoFilesIsAUsageError()
    {
        Assert.Equal(2, CliRun.Of(string.Empty, "inspect-dll").ExitCode);
        Assert.Equal(2, CliRun.Of(string.Empty, "inspect-dll", "a.dll", "b.dll").ExitCode);
    }
}
