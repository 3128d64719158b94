using URWPGSim2D.Engine.BuiltInStrategies;
using URWPGSim2D.Engine.Matches;
using URWPGSim2D.Engine.Teams;
using URWPGSim2D.Engine.Trace;
using URWPGSim2D.Strategies;

namespace URWPGSim2D.Server.Tests.Matches;

/// <summary>
/// A match whose team is driven by decisions pushed before each cycle (<see cref="PushedDecisions"/>)
/// is, line for line, the match of a strategy that returns the same decisions from the snapshot.
/// </summary>
public sealed class PushedDecisionsTests
{
    [Theory]
    [InlineData("polo-1v1", 3UL, 0)]
    [InlineData("polo-1v1", 4UL, 1)]
    [InlineData("ball-grab", 2UL, 0)]
    [InlineData("polo-3v3", 5UL, 1)]
    public void PushedDecisionsPlayTheMatchOfAStrategyDecidingTheSame(string slug, ulong seed, int team)
    {
        var item = ItemRegistry.Find(slug)!;
        var scripted = new Scripted();
        var pushed = new PushedDecisions(item.FishPerTeam);
        var teamsA = new IStrategy?[2];
        var teamsB = new IStrategy?[2];
        teamsA[team] = scripted;
        teamsB[team] = pushed;
        teamsA[1 - team] = new ChaseBallStrategy();
        teamsB[1 - team] = new ChaseBallStrategy();
        var a = MatchSetup.Create(item.CreateScenario(seed), teamsA, seed: seed, cycles: 300);
        var b = MatchSetup.Create(item.CreateScenario(seed), teamsB, seed: seed, cycles: 300);
        var lineA = new TraceLine(a.World, a.Teams, a.Rules);
        var lineB = new TraceLine(b.World, b.Teams, b.Rules);
        int moved = 0;
        for (int cycle = 0; cycle < 300 && !a.IsOver; cycle++)
        {
            Assert.Equal(lineA.Write(a.Contacts.Cycle).ToArray(), lineB.Write(b.Contacts.Cycle).ToArray());
            for (int k = 0; k < pushed.Pending.Length; k++)
            {
                pushed.Pending[k] = Scripted.At(cycle + 1, k);
            }

            a.Step();
            b.Step();
            moved += b.World.Fish[Pushed(b).Fish[0]].Speed.Value > 0f ? 1 : 0;
        }

        Assert.Equal(a.Rules.Scores, b.Rules.Scores);
        Assert.True(moved > 0, "the pushed fish never moved: the test would prove nothing");
        Assert.Equal(0, Pushed(b).Faults);
        Assert.Equal(team, Pushed(b).Team);
    }

    [Fact]
    public void ATeamSeatedWithAnotherNumberOfFishIsABadAnswer()
    {
        var item = ItemRegistry.Find("polo-3v3")!;
        var pushed = new PushedDecisions(1);
        var match = MatchSetup.Create(item.CreateScenario(1), [pushed, null], seed: 1, cycles: 10);
        match.Step();
        var seat = Assert.Single(match.Teams.Seats, s => s.Label == "pushed");
        Assert.Equal(1, seat.BadAnswers);
        Assert.Contains("made for 1 fish", seat.LastFault, StringComparison.Ordinal);
        Assert.Equal("fishCount", Assert.Throws<ArgumentOutOfRangeException>(() => new PushedDecisions(0)).ParamName);
    }

    private static TeamSeat Pushed(Match match) => Assert.Single(match.Teams.Seats, s => s.Label == "pushed");

    // Decides from the cycle alone, as the test pushes.
    private sealed class Scripted : IStrategy
    {
        public string TeamName => "pushed";

        public static Decision At(int cycle, int k) => new(((cycle * 5) + k) % 16, ((cycle * 3) + (2 * k)) % 16);

        public void Decide(MatchSnapshot snapshot, ReadOnlySpan<int> fish, Span<Decision> decisions)
        {
            for (int k = 0; k < fish.Length; k++)
            {
                decisions[k] = At(snapshot.Cycle + 1, k);
            }
        }
    }
}
