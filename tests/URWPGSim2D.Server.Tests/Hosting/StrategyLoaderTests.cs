using System.Runtime.Loader;

namespace URWPGSim2D.Server.Tests.Hosting;

/// <summary>User strategies from compiled assemblies, each in its own load context.</summary>
public sealed class StrategyLoaderTests
{
    internal const string SprinterSource = """
        using System;
        using URWPGSim2D.Strategies;
        namespace UserTeam
        {
            public sealed class Sprinter : IStrategy
            {
                public string TeamName => "sprinters";
                public void Decide(MatchSnapshot snapshot, ReadOnlySpan<int> fish, Span<Decision> decisions)
                {
                    for (int i = 0; i < decisions.Length; i++) decisions[i] = new Decision(15, 7);
                }
            }
        }
        """;

    [Fact]
    public void ALoadedStrategyRunsInItsOwnLoadContextAndDrivesItsTeam()
    {
        string dll = StrategyAssemblyBuilder.Build("Sprinters", SprinterSource);
        IStrategy strategy = StrategyResolver.Load(dll);
        Assert.Equal("sprinters", strategy.TeamName);
        Assert.IsType<StrategyLoadContext>(AssemblyLoadContext.GetLoadContext(strategy.GetType().Assembly));

        var teams = new TeamStrategy?[] { new("Sprinters.dll", strategy, Isolated: true), null };
        var match = TestMatches.FromJson("""{"fish":[{"team":0,"position":[-1000,-300]},{"team":0,"position":[-1000,300]},{"team":1,"position":[900,0]}],"balls":[]}""", teams);
        match.Play(12);
        float approached = 317f * (1f - System.MathF.Pow(0.9f, 12)); // VCode 15 for 12 cycles from rest: 317·(1 − 0.9^12)
        Assert.Equal(approached, match.World.Fish[0].Speed.Value, 1e-2f);
        Assert.Equal(approached, match.World.Fish[1].Speed.Value, 1e-2f);
        Assert.Equal(0f, match.World.Fish[2].Speed.Value);
        Assert.Equal([0, 1], match.Caller().Slots[0].Fish);
    }

    [Fact]
    public void LoadFailuresAreOneLine()
    {
        var missing = Assert.Throws<StrategyLoadException>(() => StrategyResolver.Load("no/such/Team.dll"));
        Assert.Equal("strategy assembly not found: no/such/Team.dll", missing.Message);

        string empty = StrategyAssemblyBuilder.Build("Empty", "namespace Nothing { public sealed class Here { } }");
        var none = Assert.Throws<StrategyLoadException>(() => StrategyResolver.Load(empty));
        Assert.EndsWith("Empty.dll has no public strategy class (IStrategy of URWPGSim2D.Strategies or URWPGSim2D.StrategyLoader) with a parameterless constructor", none.Message, System.StringComparison.Ordinal);

        string notDll = Path.Combine(Path.GetTempPath(), $"urwpg-not-a-dll-{System.Guid.NewGuid():N}.dll");
        File.WriteAllText(notDll, "hello");
        try
        {
            var bad = Assert.Throws<StrategyLoadException>(() => StrategyResolver.Load(notDll));
            Assert.StartsWith("cannot load strategy assembly", bad.Message, System.StringComparison.Ordinal);
            Assert.DoesNotContain('\n', bad.Message);
        }
        finally
        {
            File.Delete(notDll);
        }
    }

    [Fact]
    public void SeveralStrategiesNeedATypeName()
    {
        string source = SprinterSource + "\nnamespace UserTeam { public sealed class Idle : URWPGSim2D.Strategies.IStrategy { public string TeamName => \"i\"; public void Decide(URWPGSim2D.Strategies.MatchSnapshot s, System.ReadOnlySpan<int> f, System.Span<URWPGSim2D.Strategies.Decision> d) { } } }";
        string dll = StrategyAssemblyBuilder.Build("Two", source);
        var e = Assert.Throws<StrategyLoadException>(() => StrategyResolver.Load(dll));
        Assert.Contains("has several strategy classes (UserTeam.Idle, UserTeam.Sprinter): pick one with", e.Message, System.StringComparison.Ordinal);
        Assert.Equal("i", StrategyResolver.Load(dll + "#UserTeam.Idle").TeamName);
    }
}
