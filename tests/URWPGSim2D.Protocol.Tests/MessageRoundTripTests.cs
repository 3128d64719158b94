using URWPGSim2D.Testing;

namespace URWPGSim2D.Protocol.Tests;

/// <summary>Every message read back is what was written: snapshots bit for bit (random cases), assignments, decisions, hello, end, error.</summary>
public class MessageRoundTripTests
{
    [Fact]
    public void Cycles_cross_the_protocol_bit_for_bit()
    {
        var writer = new MessageWriter();
        Runs.RandomCases(22, 300, random =>
        {
            var assignment = RandomSnapshots.Assignment(random);
            var line = writer.Assignment(assignment).ToArray();
            var read = MessageReader.ReadAssignment(line.AsSpan(0, line.Length - 1));
            Assert.Equal(assignment.Fish, read.Fish);
            Assert.Equal(assignment.Obstacles, read.Obstacles);
            Assert.Equal(assignment with { Fish = read.Fish, Obstacles = read.Obstacles }, read);

            var server = assignment.CreateSnapshot();
            var client = new CycleReader(read);
            for (int c = 0; c < 3; c++)
            {
                RandomSnapshots.Fill(server, random, read.ItemName, read.TotalCycles);
                var cycle = writer.Cycle(server);
                Assert.Equal((byte)'\n', cycle[^1]);
                Assert.Equal(-1, cycle[..^1].IndexOf((byte)'\n'));
                Assert.Equal(MessageType.Cycle, MessageReader.TypeOf(cycle[..^1]));
                Assert.Equal(server.Cycle, client.Read(cycle[..^1]));
                RandomSnapshots.AssertSame(server, client.Snapshot);
            }
        });
    }

    [Fact]
    public void Decisions_round_trip_and_faults_keep_their_kind()
    {
        var writer = new MessageWriter();
        Decision[] sent = [new(14, 7), new(0, 15), new(3, 0)];
        var into = new Decision[3];
        var line = writer.Decisions(41, sent);
        Assert.Equal(AnswerKind.Decided, MessageReader.ReadDecisions(line[..^1], 41, into, out string? message));
        Assert.Null(message);
        Assert.Equal(sent, into);

        foreach (var kind in new[] { AnswerKind.Exception, AnswerKind.Timeout, AnswerKind.BadAnswer })
        {
            line = writer.Fault(41, kind, "boom");
            Assert.Equal(kind, MessageReader.ReadDecisions(line[..^1], 41, into, out message));
            Assert.Equal("boom", message);
        }
    }

    [Fact]
    public void Hello_end_and_error_round_trip()
    {
        var writer = new MessageWriter();
        var hello = MessageReader.ReadHello(writer.Hello(1, "tok\"en", "红队")[..^1]);
        Assert.Equal(new HelloMessage(1, "tok\"en", "红队"), hello);
        Assert.Equal(new HelloMessage(1, null, null), MessageReader.ReadHello(writer.Hello(1, null, null)[..^1]));
        foreach (int[] goals in new[] { new[] { 2, 1 }, new[] { 0, 3, 1, 7 } })
        {
            var end = MessageReader.ReadEnd(writer.End(new EndMessage(6000, goals, 5))[..^1]);
            Assert.Equal((6000, 5), (end.Cycle, end.Faults));
            Assert.Equal(goals, end.Goals);
        }

        Assert.Equal("no", MessageReader.ReadError(writer.Error("no")[..^1]));
        Assert.Equal(new string('x', ProtocolLimits.TextChars), MessageReader.ReadError(writer.Error(new string('x', 5000))[..^1]));
    }

    [Fact]
    public void A_number_that_is_not_finite_crosses_as_null_and_reads_back_as_NaN()
    {
        var writer = new MessageWriter();
        var a = new AssignmentMessage(1, 0, "", "match", [0], 1, 1, 0, 100, 3000, 2000, []);
        var server = a.CreateSnapshot();
        server.FishBuffer[0] = new FishView(0, 0, new(float.NaN, float.PositiveInfinity), 0, 0, 0, 160, 30, Decision.Stop);
        server.BallBuffer[0] = new BallView(0, default, default, 58);
        var line = writer.Cycle(server);
        Assert.Contains("\"position\":[null,null]", System.Text.Encoding.UTF8.GetString(line), StringComparison.Ordinal);
        var client = new CycleReader(a);
        client.Read(line[..^1]);
        Assert.True(float.IsNaN(client.Snapshot.Fish[0].Position.X));
        Assert.True(float.IsNaN(client.Snapshot.Fish[0].Position.Y));
    }
}
