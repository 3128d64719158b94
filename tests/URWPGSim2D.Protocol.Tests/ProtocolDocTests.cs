using System.Text.RegularExpressions;

namespace URWPGSim2D.Protocol.Tests;

/// <summary>Every message example in docs/protocol.md reads as the message its type says.</summary>
public partial class ProtocolDocTests
{
    [GeneratedRegex("```json\\n(.*?)\\n```", RegexOptions.Singleline)]
    private static partial Regex JsonBlock();

    [Fact]
    public void Every_example_of_the_protocol_page_is_a_valid_message()
    {
        string doc = File.ReadAllText(Path.Combine(AppContext.BaseDirectory, "docs", "protocol.md"));
        int seen = 0;
        AssignmentMessage? assignment = null;
        foreach (Match m in JsonBlock().Matches(doc))
        {
            byte[] line = Encoding.UTF8.GetBytes(m.Groups[1].Value);
            switch (MessageReader.TypeOf(line))
            {
                case MessageType.Hello:
                    Assert.Equal(ProtocolVersion.Current, MessageReader.ReadHello(line).Version);
                    break;
                case MessageType.Assignment:
                    assignment = MessageReader.ReadAssignment(line);
                    break;
                case MessageType.Cycle:
                    var one = assignment! with { FishCount = 1, Fish = [0] };
                    Assert.Equal(12, new CycleReader(one).Read(line));
                    break;
                case MessageType.Decisions:
                    var drawings = new DebugRecorder();
                    drawings.Reset([0, 1]);
                    var kind = MessageReader.ReadDecisions(line, 12, new Decision[2], out string? message, drawings);
                    Assert.True(kind != AnswerKind.BadAnswer, message);
                    break;
                case MessageType.End:
                    Assert.Equal(6000, MessageReader.ReadEnd(line).Cycle);
                    break;
                case MessageType.Error:
                    Assert.NotEmpty(MessageReader.ReadError(line));
                    break;
                default:
                    Assert.Fail("not a message: " + m.Groups[1].Value);
                    break;
            }

            seen++;
        }

        Assert.Equal(9, seen);
    }
}
