using System.Reflection.Metadata;
using System.Reflection.PortableExecutable;
using System.Runtime.Loader;

namespace URWPGSim2D.Server.Tests.Hosting;

/// <summary>
/// A strategy DLL compiled against the SDK's former assembly name (<c>URWPGSim2D.Strategy</c>, now the
/// type forwards to <c>URWPGSim2D.Strategies</c>) loads and plays unchanged: in its own load context,
/// where the former name is shared with the server and its types are the SDK's, in a strategy host
/// process, and as <c>inspect-dll</c> describes it. The team ships its copy of the former SDK beside it,
/// which the server does not load.
/// </summary>
public sealed class FormerSdkNameTests
{
    [Fact]
    public void TheDllReferencesTheFormerNameAndNotTheSdksName()
    {
        string dll = StrategyAssemblyBuilder.BuildAgainstFormerSdk("FormerSprinters", StrategyLoaderTests.SprinterSource);
        using var pe = new PEReader(File.OpenRead(dll));
        MetadataReader metadata = pe.GetMetadataReader();
        var names = metadata.AssemblyReferences.Select(h => metadata.GetString(metadata.GetAssemblyReference(h).Name)).ToList();
        Assert.Contains(StrategyAssemblyBuilder.FormerSdkName, names);
        Assert.DoesNotContain(typeof(IStrategy).Assembly.GetName().Name, names);
    }

    [Fact]
    public void ItLoadsInItsOwnContextWithTheSdksTypesAndDrivesItsTeam()
    {
        string dll = StrategyAssemblyBuilder.BuildAgainstFormerSdk("FormerSprinters", StrategyLoaderTests.SprinterSource);
        IStrategy strategy = StrategyResolver.Load(dll);
        Assert.Equal("sprinters", strategy.TeamName);
        Assert.IsType<StrategyLoadContext>(AssemblyLoadContext.GetLoadContext(strategy.GetType().Assembly));
        Assert.DoesNotContain(AssemblyLoadContext.GetLoadContext(strategy.GetType().Assembly)!.Assemblies, a => a.GetName().Name == StrategyAssemblyBuilder.FormerSdkName);

        var teams = new TeamStrategy?[] { new("FormerSprinters.dll", strategy, Isolated: true), null };
        var match = TestMatches.FromJson("""{"fish":[{"team":0,"position":[-1000,-300]},{"team":1,"position":[900,0]}],"balls":[]}""", teams);
        match.Play(12);
        float approached = 317f * (1f - MathF.Pow(0.9f, 12)); // VCode 15 for 12 cycles from rest: 317·(1 − 0.9^12)
        Assert.Equal(approached, match.World.Fish[0].Speed.Value, 1e-2f);
        Assert.Equal(0f, match.World.Fish[1].Speed.Value);
    }

    [Fact]
    public void ItPlaysInAStrategyHostProcess()
    {
        string dll = StrategyAssemblyBuilder.BuildAgainstFormerSdk("FormerSprinters", StrategyLoaderTests.SprinterSource);
        var run = CliRun.Of(string.Empty, "run", "--cycles", "20", "--isolation", "process", "--strategy", "1=" + dll);
        Assert.True(run.ExitCode == 0, run.Stdout + run.Stderr);
        Assert.Contains("team 1 (sprinters [FormerSprinters.dll])", run.Stdout, StringComparison.Ordinal);
        Assert.Contains("strategy faults: none", run.Stdout, StringComparison.Ordinal);
    }

    [Fact]
    public void InspectDllSaysTheFormerNameIsSharedWithTheServer()
    {
        string dll = StrategyAssemblyBuilder.BuildAgainstFormerSdk("FormerSprinters", StrategyLoaderTests.SprinterSource);
        var run = CliRun.Of(string.Empty, "inspect-dll", dll);
        Assert.True(run.ExitCode == 0, run.Stdout + run.Stderr);
        string version = typeof(IStrategy).Assembly.GetName().Version!.ToString();
        Assert.Contains($"\n  {StrategyAssemblyBuilder.FormerSdkName} {version}: shared with the server\n", run.Stdout, StringComparison.Ordinal);
        Assert.Contains("strategy API: the strategy SDK's (URWPGSim2D.Strategies.IStrategy)\n", run.Stdout, StringComparison.Ordinal);
    }
}
