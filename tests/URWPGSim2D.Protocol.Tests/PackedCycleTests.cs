using URWPGSim2D.Testing;

namespace URWPGSim2D.Protocol.Tests;

/// <summary>
/// Packed cycles (<see cref="PackedCycle"/>), for a client whose hello asks for them: the fish and balls
/// cross bit for bit, as in the JSON form (random cases, and values that are not finite); the flags are
/// said only when set; a packed field of the wrong size or not base64 is one line; a steady state allocates nothing.
/// </summary>
public class PackedCycleTests
{
    [Fact]
    public void Packed_cycles_cross_bit_for_bit_and_read_as_the_json_form_does()
    {
        var writer = new MessageWriter();
        Runs.RandomCases(37, 300, random =>
        {
            var assignment = RandomSnapshots.Assignment(random) with { Packed = true };
            var server = assignment.CreateSnapshot();
            var packed = new CycleReader(assignment);
            var json = new CycleReader(assignment);
            for (int c = 0; c < 3; c++)
            {
                RandomSnapshots.Fill(server, random, assignment.ItemName, assignment.TotalCycles);
                var line = writer.Cycle(server, packed: true).ToArray();
                Assert.Equal(-1, line.AsSpan(0, line.Length - 1).IndexOf((byte)'\n'));
                Assert.Equal(-1, line.AsSpan().IndexOf("\"fish\""u8));
                Assert.Equal(MessageType.Cycle, MessageReader.TypeOf(line.AsSpan(0, line.Length - 1)));
                Assert.Equal(server.Cycle, packed.Read(line.AsSpan(0, line.Length - 1)));
                RandomSnapshots.AssertSame(server, packed.Snapshot);
                json.Read(writer.Cycle(server)[..^1]);
                RandomSnapshots.AssertSame(json.Snapshot, packed.Snapshot);
            }
        });
    }

    [Fact]
    public void Values_that_are_not_finite_keep_their_bits_and_escaped_base64_reads_too()
    {
        var a = new AssignmentMessage(1, 0, "", "match", [0], 1, 1, 0, 100, 3000, 2000, []) { Packed = true };
        var server = a.CreateSnapshot();
        server.FishBuffer[0] = new FishView(0, 0, new(float.NaN, float.PositiveInfinity), float.NegativeInfinity, 0, 0, 160, 30, new Decision(14, 3));
        server.BallBuffer[0] = new BallView(0, new(-1.5f, 2.25f), new(1e-40f, -0f), 58);
        string line = Encoding.UTF8.GetString(new MessageWriter().Cycle(server, packed: true)[..^1]);
        var client = new CycleReader(a);
        client.Read(Encoding.UTF8.GetBytes(line));
        Assert.True(float.IsNaN(client.Snapshot.Fish[0].Position.X));
        Assert.Equal(float.PositiveInfinity, client.Snapshot.Fish[0].Position.Y);
        Assert.Equal(float.NegativeInfinity, client.Snapshot.Fish[0].Heading);
        Assert.Equal(new Decision(14, 3), client.Snapshot.Fish[0].Decision);
        Assert.Equal(BitConverter.SingleToInt32Bits(-0f), BitConverter.SingleToInt32Bits(client.Snapshot.Balls[0].Velocity.Y));
        Assert.Equal(1e-40f, client.Snapshot.Balls[0].Velocity.X);

        // A writer that escapes what it may ('+' and '/' as \u002B, \u002F) is read the same.
        string escaped = line.Replace("+", "\\u002B", StringComparison.Ordinal).Replace("/", "\\u002F", StringComparison.Ordinal);
        var other = new CycleReader(a);
        other.Read(Encoding.UTF8.GetBytes(escaped));
        RandomSnapshots.AssertSame(client.Snapshot, other.Snapshot);
    }

    [Theory]
    [InlineData("{\"type\":\"cycle\",\"cycle\":1,\"goals\":[0,0],\"packed\":\"AAAA\"}", "packed: 3 bytes, the assignment's 1 fish and 1 balls take 96")]
    [InlineData("{\"type\":\"cycle\",\"cycle\":1,\"goals\":[0,0],\"packed\":\"not base64!\"}", "packed: not base64")]
    [InlineData("{\"type\":\"cycle\",\"cycle\":1,\"goals\":[0,0],\"packed\":7}", "packed: expected a string, got the number 7")]
    public void A_bad_packed_field_is_one_line(string line, string error)
    {
        var a = new AssignmentMessage(1, 0, "", "match", [0], 1, 1, 0, 100, 3000, 2000, []) { Packed = true };
        var e = Assert.Throws<ProtocolException>(() => new CycleReader(a).Read(Encoding.UTF8.GetBytes(line)));
        Assert.Equal(error, e.Message);
    }

    [Fact]
    public void Hello_and_assignment_say_packed_only_when_it_is_asked_for()
    {
        var writer = new MessageWriter();
        Assert.True(MessageReader.ReadHello(writer.Hello(1, null, "x", packed: true)[..^1]).Packed);
        Assert.DoesNotContain("packed", Encoding.UTF8.GetString(writer.Hello(1, null, "x")), StringComparison.Ordinal);
        Assert.False(MessageReader.ReadHello(writer.Hello(1, null, "x")[..^1]).Packed);
        var a = new AssignmentMessage(1, 0, "", "match", [0], 1, 1, 0, 100, 3000, 2000, []);
        Assert.DoesNotContain("packed", Encoding.UTF8.GetString(writer.Assignment(a)), StringComparison.Ordinal);
        Assert.True(MessageReader.ReadAssignment(writer.Assignment(a with { Packed = true })[..^1]).Packed);
    }

    [Fact]
    public void A_packed_cycle_allocates_nothing_in_a_steady_state()
    {
        var assignment = new AssignmentMessage(1, 0, "ball-grab", "match", [0, 1], 4, 9, 6000, 100, 3000, 2000, []) { Packed = true };
        var server = assignment.CreateSnapshot();
        RandomSnapshots.Fill(server, new Random(6), "match", 6000);
        server.SetItem("match", new OrderedVariables(), 6000); // no variables: enumerating them through the dictionary's interface allocates, in either form
        var writer = new MessageWriter();
        var client = new CycleReader(assignment);

        void Once() => client.Read(writer.Cycle(server, packed: true)[..^1]);

        Assert.Equal(0, Runs.SteadyStateAllocations(Once));
    }
}
