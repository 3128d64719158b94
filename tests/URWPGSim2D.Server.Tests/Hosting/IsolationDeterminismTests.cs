namespace URWPGSim2D.Server.Tests.Hosting;

/// <summary>
/// A well-behaved strategy plays the same match in a sandboxed strategy host as in the server's
/// process: the traces are byte-identical for every item, two seeds each, with an SDK strategy and
/// with one in the original's API (which reads the item's mission variables and the half-time swap).
/// </summary>
[Collection(InProcessStaticsCollection.Name)]
public sealed class IsolationDeterminismTests() : TempFolderTest("urwpg-same-")
{
    // Long enough for every item's half-time swap (at cycle 20) and a few hundred decisions; the point is the identity, not the length.
    private const string Cycles = "40";

    // A deadline no honest call comes near even on a loaded machine (a missed one would change the match, not the code under test).
    private const string Deadline = "5000";

    public static IEnumerable<object[]> Items()
    {
        foreach (var item in ItemRegistry.All)
        {
            yield return [item.Slug];
        }
    }

    [Theory]
    [MemberData(nameof(Items))]
    public void A_hosted_strategy_plays_the_same_match_as_in_process(string item)
    {
        string sdk = SteadyStrategy.Write(Folder);
        foreach (string spec in new[] { sdk, OriginalStrategyTests.Folder("Dribbler") })
        {
            foreach (string seed in new[] { "1", "2" })
            {
                string inProcess = Path.Combine(Folder, "none.jsonl"), hosted = Path.Combine(Folder, "process.jsonl");
                var a = CliRun.Of(string.Empty, "run", "--item", item, "--seed", seed, "--cycles", Cycles, "--strategy", "0=" + spec, "--force", "--trace", inProcess, "--isolation", "none", "--strategy-timeout", Deadline);
                var b = CliRun.Of(string.Empty, "run", "--item", item, "--seed", seed, "--cycles", Cycles, "--strategy", "0=" + spec, "--force", "--trace", hosted, "--sandbox", "required", "--strategy-timeout", Deadline);
                Assert.True(a.ExitCode == 0 && b.ExitCode == 0, a.Stderr + b.Stderr);
                Assert.Contains("strategy faults: none", a.Stdout, StringComparison.Ordinal);
                Assert.Contains("strategy faults: none", b.Stdout, StringComparison.Ordinal);
                Assert.True(File.ReadAllBytes(inProcess).AsSpan().SequenceEqual(File.ReadAllBytes(hosted)), $"{item} seed {seed} {Path.GetFileName(spec)}: the traces differ");
            }
        }
    }
}
