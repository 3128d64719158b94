using URWPGSim2D.Strategies;

namespace URWPGSim2D.Protocol.Tests;

/// <summary>The per-cycle messages allocate nothing once the buffers have grown (the hot path of an isolated team).</summary>
public class ProtocolAllocationTests
{
    [Theory]
    [InlineData(false)]
    [InlineData(true)] // an item's mission variables, as every item's match has them
    public void A_cycle_and_its_decisions_allocate_nothing_in_a_steady_state(bool variables)
    {
        var random = new Random(5);
        var assignment = new AssignmentMessage(1, 0, "ball-grab", "match", [0, 1], 4, 1, 6000, 100, 3000, 2000, []);
        var server = assignment.CreateSnapshot();
        RandomSnapshots.Fill(server, random, "match", 6000);
        if (variables)
        {
            var table = new OrderedVariables();
            table.Set("phase", "first half");
            table.Set("剩余时间", "600");
            table.Set("score", "3:4");
            server.SetItem("match", table, 6000);
        }
        var writer = new MessageWriter();
        var client = new CycleReader(assignment);
        var answer = new MessageWriter();
        Decision[] decisions = [new(3, 4), new(5, 6)];
        var read = new Decision[2];

        void Once()
        {
            var line = writer.Cycle(server);
            int c = client.Read(line[..^1]);
            var back = answer.Decisions(c, decisions);
            MessageReader.ReadDecisions(back[..^1], c, read, out _);
        }

        Assert.Equal(0, Runs.SteadyStateAllocations(Once));
        Assert.Equal(decisions, read);
        Assert.Equal(server.Variables, client.Snapshot.Variables);
    }
}
