using System.Numerics;
using URWPGSim2D.Strategies;

namespace URWPGSim2D.Protocol.Tests;

/// <summary>A strategy's debug drawings cross the protocol in a decisions message's <c>draw</c>, shape for shape; a malformed one is an error naming it.</summary>
public sealed class DebugDrawMessageTests
{
    private static DebugRecorder Drawn(int[] fish)
    {
        var r = new DebugRecorder();
        r.Enter(fish);
        DebugDraw.Point(new Vector2(1.5f, -2.25f), fish[0], 0x123456);
        DebugDraw.Line(new Vector2(-1000f, 0.1f), new Vector2(3f, 4f), fish[1]);
        DebugDraw.Circle(new Vector2(7f, 8f), 58f, -1, 0xffd400);
        DebugDraw.Text(new Vector2(0f, 0f), "plan \"A\" → goal", fish[0]);
        DebugRecorder.Exit();
        return r;
    }

    [Fact]
    public void Drawings_round_trip_through_a_decisions_message()
    {
        int[] fish = [2, 3];
        var sent = Drawn(fish);
        var writer = new MessageWriter();
        var line = writer.Decisions(41, [new Decision(3, 4), new Decision(5, 6)], sent).ToArray();
        var got = new DebugRecorder();
        got.Reset(fish);
        var decisions = new Decision[2];
        Assert.Equal(AnswerKind.Decided, MessageReader.ReadDecisions(line, 41, decisions, out _, got));
        Assert.Equal(new Decision(5, 6), decisions[1]);
        Assert.Equal(sent.Shapes.ToArray(), got.Shapes.ToArray());

        // A reader that does not record drawings skips them.
        Assert.Equal(AnswerKind.Decided, MessageReader.ReadDecisions(line, 41, decisions, out _));
    }

    [Fact]
    public void A_strategys_output_round_trips_with_the_count_it_dropped()
    {
        var line = new MessageWriter().Decisions(3, [Decision.Stop], null, "saw \"cycle\" 3\n", 17).ToArray();
        var printed = new PrintedOutput();
        Assert.Equal(AnswerKind.Decided, MessageReader.ReadDecisions(line, 3, new Decision[1], out _, null, printed));
        Assert.Equal("saw \"cycle\" 3\n", printed.Text.ToString());
        Assert.Equal(17, printed.Dropped);
    }

    [Fact]
    public void Without_drawings_a_decisions_message_is_unchanged()
    {
        var writer = new MessageWriter();
        string plain = Encoding.UTF8.GetString(writer.Decisions(1, [Decision.Stop]));
        var empty = new DebugRecorder();
        empty.Reset([0]);
        Assert.Equal(plain, Encoding.UTF8.GetString(writer.Decisions(1, [Decision.Stop], empty)));
        Assert.Equal("{\"type\":\"decisions\",\"cycle\":1,\"decisions\":[[0,7]]}\n", plain);
    }

    [Theory]
    [InlineData("""[{"kind":"square","at":[0,0]}]""", "draw[0].kind: expected point, line, circle or text, got \"square\"")]
    [InlineData("""[{"kind":"point","at":[0,0],"color":"red"}]""", "draw[0].color: expected \"#rrggbb\", got \"red\"")]
    [InlineData("""[{"kind":"line","from":[0,0]}]""", "draw[0].to: missing")]
    [InlineData("""[{"kind":"text","at":[0,0]}]""", "draw[0].text: missing")]
    [InlineData("""[{"kind":"circle","radius":3}]""", "draw[0]: a shape needs at, from or center")]
    [InlineData("""[3]""", "draw[0]: expected an object, got the number 3")]
    [InlineData("""{"kind":"point"}""", "draw: expected an array, got an object")]
    public void A_malformed_drawing_is_an_error_naming_it(string draw, string error)
    {
        byte[] line = Encoding.UTF8.GetBytes("{\"type\":\"decisions\",\"cycle\":0,\"decisions\":[[1,2]],\"draw\":" + draw + "}");
        var into = new DebugRecorder();
        into.Reset([0]);
        var e = Assert.Throws<ProtocolException>(() => MessageReader.ReadDecisions(line, 0, new Decision[1], out _, into));
        Assert.Equal(error, e.Message);
    }

    [Fact]
    public void The_assignment_says_draw_only_when_drawings_are_recorded()
    {
        var a = new AssignmentMessage(1, 0, "", "match", [0], 1, 0, 0, 100, 3000f, 2000f, []);
        var writer = new MessageWriter();
        string plain = Encoding.UTF8.GetString(writer.Assignment(a));
        Assert.DoesNotContain("draw", plain, StringComparison.Ordinal);
        Assert.False(MessageReader.ReadAssignment(Encoding.UTF8.GetBytes(plain)).Draw);
        string drawn = Encoding.UTF8.GetString(writer.Assignment(a with { Draw = true }));
        Assert.Contains("\"draw\":true", drawn, StringComparison.Ordinal);
        Assert.True(MessageReader.ReadAssignment(Encoding.UTF8.GetBytes(drawn)).Draw);
    }
}
