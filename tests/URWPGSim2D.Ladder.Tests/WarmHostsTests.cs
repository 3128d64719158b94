using URWPGSim2D.Engine.Items.Catalog;
using URWPGSim2D.Hosting;
using URWPGSim2D.Tournament;

namespace URWPGSim2D.Ladder.Tests;

/// <summary>
/// Started strategy hosts wait only for the submissions used last: with a bound of two, readying a
/// third submission ends the waiting host of the one used longest ago (its process is gone), and a
/// submission used again gets a waiting host again. However many submissions a service readies, at
/// most the bound keep a host.
/// </summary>
public sealed class WarmHostsTests : IDisposable
{
    private readonly string _folder = Directory.CreateTempSubdirectory("urwpg-ladder-warm-").FullName;

    public void Dispose() => Directory.Delete(_folder, recursive: true);

    private Entrant Source(string name)
    {
        string file = Path.Combine(_folder, name, name + ".cs");
        Directory.CreateDirectory(Path.GetDirectoryName(file)!);
        File.WriteAllText(file, "using System; using URWPGSim2D.Strategies;\n" + $$"""
            public sealed class {{name}} : IStrategy
            {
                public string TeamName => "{{name}}";
                public void Decide(MatchSnapshot s, ReadOnlySpan<int> fish, Span<Decision> d) { }
            }
            """);
        return new Entrant(name, file);
    }

    private static bool Alive(int pid) => Directory.Exists($"/proc/{pid}") && !File.ReadAllText($"/proc/{pid}/stat").Split(' ')[2].Equals("Z", StringComparison.Ordinal);

    [Fact]
    public async Task OnlyTheSubmissionsUsedLastKeepAWaitingHost()
    {
        var player = new LadderMatchPlayer(ItemRegistry.Find("polo-1v1")!, HostSettings.Default, 100, warmLimit: 2);
        var entrants = new[] { Source("Alpha"), Source("Beta"), Source("Gamma") };
        var loaders = new List<EntrantLoader>();
        for (int k = 0; k < 2; k++)
        {
            loaders.Add(player.Loader(k + 1, k + 1, entrants[k]));
        }

        await LadderHost.Until(() => Task.FromResult(loaders.All(l => l.WaitingHosts().Count == 1)), "a host waits for each of the two");
        int alpha = Assert.Single(loaders[0].WaitingHosts());

        // A third: the one used longest ago (Alpha) keeps no host, and its process has ended.
        loaders.Add(player.Loader(3, 3, entrants[2]));
        Assert.Empty(loaders[0].WaitingHosts());
        await LadderHost.Until(() => Task.FromResult(!Alive(alpha)), "Alpha's waiting host ended", minutes: 1);
        await LadderHost.Until(() => Task.FromResult(loaders[2].WaitingHosts().Count == 1), "a host waits for Gamma");
        Assert.Single(loaders[1].WaitingHosts());

        // Alpha used again: the same readied submission (not compiled again), warm again; now Beta is the one used longest ago.
        Assert.Same(loaders[0], player.Loader(1, 1, entrants[0]));
        Assert.Empty(loaders[1].WaitingHosts());
        await LadderHost.Until(() => Task.FromResult(loaders[0].WaitingHosts().Count == 1), "a host waits for Alpha again");
        Assert.Equal(2, loaders.Count(l => l.WaitingHosts().Count > 0));
        foreach (var l in loaders)
        {
            l.Release();
        }

        Assert.All(loaders, l => Assert.Empty(l.WaitingHosts()));
    }
}
