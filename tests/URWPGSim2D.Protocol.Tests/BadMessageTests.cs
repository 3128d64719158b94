namespace URWPGSim2D.Protocol.Tests;

/// <summary>What a reader does with broken or hostile lines: one-line errors naming the field, bad answers with the reason, unknown fields skipped.</summary>
public class BadMessageTests
{
    private static byte[] L(string s) => Encoding.UTF8.GetBytes(s);

    [Theory]
    [InlineData("", "not a JSON message")]
    [InlineData("[1,2]", "a message must be one JSON object")]
    [InlineData("{\"type\":", "not a JSON message")]
    [InlineData("nonsense", "not a JSON message")]
    [InlineData("{\"type\":3}", "type: expected a string, got the number 3")]
    public void A_line_that_is_not_a_message_is_refused_with_one_line(string line, string error)
    {
        var e = Assert.Throws<ProtocolException>(() => MessageReader.TypeOf(L(line)));
        Assert.StartsWith(error, e.Message, StringComparison.Ordinal);
        Assert.DoesNotContain('\n', e.Message);
    }

    [Fact]
    public void Unknown_types_and_fields_are_told_apart_from_known_ones()
    {
        Assert.Equal(MessageType.Unknown, MessageReader.TypeOf(L("{\"type\":\"ping\"}")));
        Assert.Equal(MessageType.Unknown, MessageReader.TypeOf(L("{\"cycle\":1}")));
        Assert.Equal(MessageType.Decisions, MessageReader.TypeOf(L("{\"extra\":{\"a\":[1,{}]},\"type\":\"decisions\"}")));
        var into = new Decision[1];
        Assert.Equal(AnswerKind.Decided, MessageReader.ReadDecisions(L("{\"new\":[1,2],\"decisions\":[[1,2]],\"type\":\"decisions\",\"cycle\":3}"), 3, into, out _));
        Assert.Equal(new Decision(1, 2), into[0]);
    }

    [Theory]
    [InlineData("{\"cycle\":3,\"decisions\":[[1,2],[3,4]]}", "decisions: 2 for 1 fish")]
    [InlineData("{\"cycle\":3,\"decisions\":[]}", "decisions: 0 for 1 fish")]
    [InlineData("{\"cycle\":3}", "decisions: missing")]
    [InlineData("{\"cycle\":3,\"decisions\":[[16,2]]}", "decisions[0][0]: expected a gear 0..15, got the number 16")]
    [InlineData("{\"cycle\":3,\"decisions\":[[1,-1]]}", "decisions[0][1]: expected a gear 0..15, got the number -1")]
    [InlineData("{\"cycle\":3,\"decisions\":[[1.5,2]]}", "decisions[0][0]: expected a gear 0..15, got the number 1.5")]
    [InlineData("{\"cycle\":3,\"decisions\":[[1,\"2\"]]}", "decisions[0][1]: expected a gear 0..15, got a string")]
    [InlineData("{\"cycle\":3,\"decisions\":[[1]]}", "decisions[0]: expected [vcode, tcode], got 1 values")]
    [InlineData("{\"cycle\":3,\"decisions\":[7]}", "decisions[0]: expected [vcode, tcode], got the number 7")]
    [InlineData("{\"cycle\":3,\"fault\":\"whatever\"}", "(no message)")]
    public void Unusable_decisions_are_a_bad_answer_with_the_reason(string line, string reason)
    {
        var into = new Decision[1];
        Assert.Equal(AnswerKind.BadAnswer, MessageReader.ReadDecisions(L(line), 3, into, out string? message));
        Assert.Equal(reason, message);
    }

    [Theory]
    [InlineData("{\"cycle\":2,\"decisions\":[[1,2]]}", "cycle: answered cycle 2, expected 3")]
    [InlineData("{\"decisions\":[[1,2]]}", "cycle: missing")]
    [InlineData("{\"cycle\":\"3\",\"decisions\":[[1,2]]}", "cycle: expected an integer, got a string")]
    [InlineData("{\"cycle\":3,\"decisions\":[[1,2]]", "not a JSON message")]
    public void An_answer_for_another_cycle_or_without_one_is_refused(string line, string error)
    {
        var e = Assert.Throws<ProtocolException>(() => MessageReader.ReadDecisions(L(line), 3, new Decision[1], out _));
        Assert.StartsWith(error, e.Message, StringComparison.Ordinal);
    }

    [Theory]
    [InlineData("{\"type\":\"hello\"}", "version: missing")]
    [InlineData("{\"type\":\"hello\",\"version\":1.5}", "version: expected an integer, got the number 1.5")]
    [InlineData("{\"type\":\"hello\",\"version\":1,\"token\":5}", "token: expected a string, got the number 5")]
    public void A_bad_hello_names_the_field(string line, string error)
    {
        var e = Assert.Throws<ProtocolException>(() => MessageReader.ReadHello(L(line)));
        Assert.Equal(error, e.Message);
    }

    [Theory]
    [InlineData("\"team\":4", "team: 4 is not 0 to 3")]
    [InlineData("\"team\":-1", "team: -1 is not 0 to 3")]
    [InlineData("\"fish\":[4]", "fish: 4 is not a fish index below fishCount 4")]
    [InlineData("\"fish\":[0],\"field\":{\"width\":2}", "field.length: missing")]
    [InlineData("\"obstacles\":[{\"index\":0,\"kind\":\"hexagon\",\"center\":[0,0]}]", "obstacles.kind: expected round or rectangle, got hexagon")]
    [InlineData("\"obstacles\":[{\"index\":0,\"kind\":\"round\",\"center\":[0]}]", "obstacles.center: expected 2 numbers, got 1")]
    public void A_bad_assignment_names_the_field(string field, string error)
    {
        string line = "{\"type\":\"assignment\",\"version\":1,\"team\":0,\"fish\":[0],\"fishCount\":4,\"ballCount\":1,\"deadlineMs\":100,\"field\":{\"length\":3000,\"width\":2000}," + field + "}";
        var e = Assert.Throws<ProtocolException>(() => MessageReader.ReadAssignment(L(line)));
        Assert.Equal(error, e.Message);
    }

    [Theory]
    [InlineData("{\"cycle\":1,\"goals\":[0,0],\"fish\":[],\"balls\":[]}", "fish: 0 fish, the assignment said 1")]
    [InlineData("{\"cycle\":1,\"goals\":[0,0],\"fish\":[{\"index\":0}],\"balls\":[]}", "fish[0]: a field is missing")]
    [InlineData("{\"cycle\":1,\"goals\":[0],\"fish\":[],\"balls\":[]}", "goals: expected 2 or 4 integers, got 1")]
    [InlineData("{\"cycle\":1,\"goals\":[0,0,0],\"fish\":[],\"balls\":[]}", "goals: expected 2 or 4 integers, got 3")]
    [InlineData("{\"cycle\":1,\"goals\":[0,0,0,0,0],\"fish\":[],\"balls\":[]}", "goals: expected 2 or 4 integers, got more")]
    [InlineData("{\"cycle\":1,\"variables\":{\"a\":1}}", "variables.a: expected a string, got the number 1")]
    public void A_bad_cycle_names_the_field(string line, string error)
    {
        var reader = new CycleReader(new AssignmentMessage(1, 0, "", "match", [0], 1, 0, 0, 100, 3000, 2000, []));
        var e = Assert.Throws<ProtocolException>(() => reader.Read(L(line)));
        Assert.StartsWith(error, e.Message, StringComparison.Ordinal);
    }
}
