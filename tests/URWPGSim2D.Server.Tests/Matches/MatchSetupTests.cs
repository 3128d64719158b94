using URWPGSim2D.Engine.BuiltInStrategies;
using URWPGSim2D.Engine.Matches;
using URWPGSim2D.Engine.Teams;
using URWPGSim2D.Engine.Trace;
using URWPGSim2D.Server.Tests.Items;
using URWPGSim2D.Strategies;

namespace URWPGSim2D.Server.Tests.Matches;

/// <summary>
/// A match built by the engine alone (<see cref="MatchSetup.Create"/>, strategies in the calling
/// program) is the match the server builds (<see cref="MatchBuilder"/>) of the same scenario and
/// seed: the same trace, line for line; a team given a strategy plays it with all of its fish; a
/// strategy that throws is charged and its fish keep their decisions.
/// </summary>
public sealed class MatchSetupTests
{
    [Theory]
    [MemberData(nameof(ItemMatches.Slugs), MemberType = typeof(ItemMatches))]
    public void TheEnginesMatchIsTheServersLineForLine(string slug)
    {
        foreach (ulong seed in new ulong[] { 1, 6 })
        {
            var item = ItemRegistry.Find(slug)!;
            var server = MatchBuilder.Build(item.CreateScenario(seed), new TeamStrategy?[Math.Max(2, item.TeamCount)], seed: seed, cycles: 400);
            var engine = MatchSetup.Create(item.CreateScenario(seed), seed: seed, cycles: 400);
            Assert.Equal(Labels(server), Labels(engine));
            var a = new TraceLine(server.World, server.Teams, server.Rules);
            var b = new TraceLine(engine.World, engine.Teams, engine.Rules);
            for (int cycle = 0; cycle <= 400 && !server.IsOver; cycle++)
            {
                Assert.Equal(a.Write(server.Contacts.Cycle).ToArray(), b.Write(engine.Contacts.Cycle).ToArray());
                server.Step();
                engine.Step();
            }

            Assert.Equal(server.Rules.Scores, engine.Rules.Scores);
            server.Teams.Stop();
            engine.Teams.Stop();
        }
    }

    [Fact]
    public void ATeamsOwnStrategyTakesAllItsFishAndAThrowIsCharged()
    {
        var thrower = new Thrower();
        var match = MatchSetup.Create(DefaultScenario.Load(), [thrower, null], cycles: 50);
        var own = Assert.Single(match.Teams.Seats, s => s.Team == 0);
        Assert.Equal("thrower", own.Label);
        Assert.Equal(match.World.Fish.Where(f => f.Team == 0).Select(f => f.Index), own.Fish);
        Assert.DoesNotContain(match.Teams.Seats, s => s.Team == 1 && s.Label == "thrower");
        for (int i = 0; i < 10; i++)
        {
            match.Step();
        }

        // It decided "full ahead" once, then threw: the fish keep that decision, every throw counted.
        Assert.Equal(9, own.Exceptions);
        Assert.Equal("InvalidOperationException: again", own.LastFault);
        Assert.All(own.Fish, f => Assert.Equal(new Decision(14, 7), match.World.Fish[f].Decision));
    }

    [Fact]
    public void BadArgumentsAreRefusedByName()
    {
        Assert.Equal("scenario", Assert.Throws<ArgumentNullException>(() => MatchSetup.Create(null!)).ParamName);
        var demo = new ScenarioDefinition { Fish = [new FishDefinition(0, System.Numerics.Vector2.Zero, 0f, "demo", Decision.Stop)] };
        Assert.Equal("scenario", Assert.Throws<ArgumentException>(() => MatchSetup.Create(demo)).ParamName);
    }

    private static List<string> Labels(Engine.Matches.Match match) => [.. match.Teams.Seats.Select(s => $"{s.Team}:{s.Label}:{string.Join(",", s.Fish)}")];

    private sealed class Thrower : IStrategy
    {
        private int _calls;

        public string TeamName => "thrower";

        public void Decide(MatchSnapshot snapshot, ReadOnlySpan<int> fish, Span<Decision> decisions)
        {
            if (_calls++ > 0)
            {
                throw new InvalidOperationException("again");
            }

            decisions.Fill(new Decision(14, 7));
        }
    }
}
