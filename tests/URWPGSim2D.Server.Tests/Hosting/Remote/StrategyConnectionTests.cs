using URWPGSim2D.Protocol;
using URWPGSim2D.Engine.Matches;

namespace URWPGSim2D.Server.Tests.Hosting.Remote;

/// <summary>
/// The server's side of the protocol (one code path for hosts and remote clients) against a
/// scripted client: hello and token, decisions, what an answer may get wrong (each a bad answer for
/// its cycle, logged, the connection going on), late answers dropped when they come, and a line
/// over the limit that closes the connection.
/// </summary>
public sealed class StrategyConnectionTests
{
    private const string Hello = "{\"type\":\"hello\",\"version\":1,\"token\":\"t0k\",\"name\":\"scripted\"}\n";
    private readonly Match _match = MatchBuilder.Build(DefaultScenario.Load(), null, cycles: 1000);
    private readonly List<string> _log = [];

    internal static string Answer(int cycle, params int[] gears)
    {
        var pairs = new List<string>();
        for (int i = 0; i < gears.Length; i += 2)
        {
            pairs.Add($"[{gears[i]},{gears[i + 1]}]");
        }

        return $"{{\"type\":\"decisions\",\"cycle\":{cycle},\"decisions\":[{string.Join(',', pairs)}]}}\n";
    }

    [Fact]
    public void A_client_says_hello_gets_the_assignment_and_its_decisions_are_taken_unknown_fields_ignored()
    {
        var link = new ScriptedLink()
            .Send("{\"type\":\"hello\",\"version\":1,\"token\":\"t0k\",\"future\":{\"nested\":[1,{\"x\":null}]},\"name\":\"scripted\"}\n")
            .Send("{\"extra\":\"ignored\",\"type\":\"decisions\",\"cycle\":0,\"decisions\":[[3,4],[15,0]],\"more\":[true]}\n");
        var connection = Connect(link, "t0k");
        var decisions = new Decision[2];
        Assert.Equal(ConnectionOutcome.Decided, connection.Decide(Next(), decisions, out _));
        Assert.Equal([new Decision(3, 4), new Decision(15, 0)], decisions);
        Assert.Equal("scripted", connection.TeamName);
        Assert.StartsWith("{\"type\":\"assignment\"", link.Written[0], StringComparison.Ordinal);
        Assert.StartsWith("{\"type\":\"cycle\",\"cycle\":0,", link.Written[1], StringComparison.Ordinal);
        Assert.Empty(_log);
    }

    [Theory]
    [InlineData("{\"type\":\"decisions\",\"cycle\":5,\"decisions\":[[1,1],[1,1]]}", "cycle: answered cycle 5, expected 0")]
    [InlineData("{\"type\":\"decisions\",\"cycle\":\"0\",\"decisions\":[[1,1],[1,1]]}", "cycle: expected an integer")]
    [InlineData("{\"type\":\"decisions\",\"cycle\":0,\"decisions\":\"fast\"}", "decisions")]
    [InlineData("{\"type\":\"decisions\",\"cycle\":0,\"decisions\":[[1,1]]}", "decisions: 1 for 2 fish")]
    [InlineData("{\"type\":\"decisions\",\"cycle\":0,\"decisions\":[[1,16],[1,1]]}", "16")]
    [InlineData("{\"type\":\"decisions\",\"cycle\":0,\"decisions\":[[1.5,1],[1,1]]}", "decisions")]
    [InlineData("{\"type\":\"decisions\",\"decisions\":[[1,1],[1,1]]}", "cycle: missing")]
    [InlineData("{\"type\":\"hello\",\"version\":1}", "something other than decisions")]
    [InlineData("[14,7]", "JSON object")]
    [InlineData("not json at all", "")]
    public void A_bad_answer_is_that_cycles_fault_logged_in_one_line_and_the_connection_goes_on(string answer, string why)
    {
        var link = new ScriptedLink().Send(Hello).Send(answer + "\n").Send(Answer(1, 9, 8, 7, 6));
        var connection = Connect(link, null);
        var decisions = new Decision[] { new(2, 2), new(2, 2) };
        Assert.Equal(ConnectionOutcome.BadAnswer, connection.Decide(Next(), decisions, out string? message));
        Assert.Contains(why, message, StringComparison.Ordinal);
        Assert.Equal([new Decision(2, 2), new Decision(2, 2)], decisions);
        string logged = Assert.Single(_log);
        Assert.StartsWith("cycle 1: bad answer: ", logged, StringComparison.Ordinal);
        Assert.DoesNotContain('\n', logged);
        Assert.Equal(ConnectionOutcome.Decided, connection.Decide(Next(), decisions, out _));
        Assert.Equal([new Decision(9, 8), new Decision(7, 6)], decisions);
    }

    [Fact]
    public void A_late_answer_is_given_up_on_and_is_dropped_when_it_comes()
    {
        var link = new ScriptedLink().Send(Hello).RunLate().Send(Answer(0, 1, 1, 1, 1)).Send(Answer(1, 5, 6, 7, 8));
        var connection = Connect(link, null);
        var decisions = new Decision[] { new(2, 2), new(2, 2) };
        Assert.Equal(ConnectionOutcome.GivenUp, connection.Decide(Next(), decisions, out string? message));
        Assert.Equal("no answer within 1.0 s", message);
        Assert.Equal([new Decision(2, 2), new Decision(2, 2)], decisions);
        Assert.Equal(ConnectionOutcome.Decided, connection.Decide(Next(), decisions, out _));
        Assert.Equal([new Decision(5, 6), new Decision(7, 8)], decisions);
        Assert.Empty(_log);
    }

    [Fact]
    public void A_line_over_the_limit_is_a_bad_answer_and_closes_the_connection()
    {
        var link = new ScriptedLink().Send(Hello).Send("{\"type\":\"decisions\",\"pad\":\"" + new string('x', ProtocolLimits.ClientLineBytes) + "\"}\n").Send(Answer(0, 1, 1, 1, 1));
        var connection = Connect(link, null);
        Assert.Equal(ConnectionOutcome.BadAnswer, connection.Decide(Next(), new Decision[2], out string? message));
        Assert.Equal("a line is longer than 65536 bytes", message);
        Assert.True(connection.HasEnded);
        Assert.StartsWith("the server closed the connection after the overlong line", connection.EndedBy, StringComparison.Ordinal);
        Assert.True(link.Aborted);
        Assert.Contains(_log, l => l.Contains("connection closed", StringComparison.Ordinal));
        Assert.Equal(ConnectionOutcome.Ended, connection.Decide(Next(), new Decision[2], out _));
    }

    [Theory]
    [InlineData("{\"type\":\"hello\",\"version\":1,\"token\":\"guess\"}", "wrong token")]
    [InlineData("{\"type\":\"hello\",\"version\":1}", "this slot needs a token")]
    [InlineData("{\"type\":\"hello\",\"version\":2,\"token\":\"t0k\"}", "protocol version 2 is not supported (this server speaks 1)")]
    [InlineData("{\"type\":\"decisions\",\"cycle\":0}", "the client did not say hello")]
    [InlineData("{\"type\":\"hello\",\"version\":\"1\",\"token\":\"t0k\"}", "hello: version: expected an integer")]
    public void A_client_without_the_right_hello_is_refused_with_an_error_and_logged(string hello, string why)
    {
        var link = new ScriptedLink().Send(hello + "\n").Send(Answer(0, 1, 1, 1, 1));
        var connection = Connect(link, "t0k");
        Assert.False(connection.Handshake(out string? message));
        Assert.StartsWith(why, message, StringComparison.Ordinal);
        Assert.True(link.Aborted);
        Assert.StartsWith("{\"type\":\"error\",\"message\":", Assert.Single(link.Written), StringComparison.Ordinal);
        Assert.Equal("refused a client: " + message, Assert.Single(_log));
        Assert.Equal(ConnectionOutcome.Ended, connection.Decide(Next(), new Decision[2], out _));
    }

    [Fact]
    public void A_client_that_goes_away_ends_the_connection()
    {
        var link = new ScriptedLink().Send(Hello).Send(Answer(0, 1, 2, 3, 4));
        var connection = Connect(link, null);
        var decisions = new Decision[2];
        Assert.Equal(ConnectionOutcome.Decided, connection.Decide(Next(), decisions, out _));
        Assert.Equal(ConnectionOutcome.Ended, connection.Decide(Next(), decisions, out string? message));
        Assert.Equal("the scripted client went away", message);
        Assert.True(connection.HasEnded);
    }

    /// <summary>
    /// Fuzz: 300 seeded scripts of mangled answers (bytes flipped, cut, spliced; fields of the wrong
    /// type; late reads; stray newlines). The server never throws, writes decisions only when it
    /// takes an answer, and then only valid gears for every fish; once ended it stays ended; every
    /// logged line is one line.
    /// </summary>
    [Fact]
    public void The_server_side_survives_any_answer()
    {
        var random = new Random(24);
        var outcomes = new HashSet<ConnectionOutcome>();
        for (int script = 0; script < 300; script++)
        {
            var match = MatchBuilder.Build(DefaultScenario.Load(), null, cycles: 1000);
            var link = new ScriptedLink().Send(Hello);
            const int cycles = 8;
            for (int c = 0; c < cycles; c++)
            {
                foreach (object part in Mangled(random, c))
                {
                    if (ReferenceEquals(part, ScriptedLink.Late))
                    {
                        link.RunLate();
                    }
                    else
                    {
                        link.Send((byte[])part);
                    }
                }
            }

            _log.Clear();
            var connection = Connect(link, null);
            bool ended = false;
            for (int c = 0; c < cycles; c++)
            {
                match.Step();
                var decisions = new Decision[] { new(99, 99), new(99, 99) };
                var outcome = connection.Decide(match.Snapshot, decisions, out string? message);
                outcomes.Add(outcome);
                if (outcome == ConnectionOutcome.Decided)
                {
                    Assert.All(decisions, d => Assert.True(d.VCode is >= 0 and <= 15 && d.TCode is >= 0 and <= 15, $"script {script}: {d}"));
                }
                else
                {
                    Assert.All(decisions, d => Assert.Equal(new Decision(99, 99), d));
                    Assert.NotNull(outcome is ConnectionOutcome.TimedOut or ConnectionOutcome.GivenUp ? "late" : message);
                }

                Assert.False(ended && outcome != ConnectionOutcome.Ended, $"script {script}: an ended connection answered {outcome}");
                ended |= outcome == ConnectionOutcome.Ended;
            }

            Assert.All(_log, l => Assert.DoesNotContain('\n', l));
        }

        Assert.Superset(new HashSet<ConnectionOutcome> { ConnectionOutcome.Decided, ConnectionOutcome.BadAnswer, ConnectionOutcome.GivenUp, ConnectionOutcome.Ended }, outcomes);
    }

    // What a hostile or broken client might send for one cycle.
    private static IEnumerable<object> Mangled(Random random, int cycle)
    {
        byte[] good = System.Text.Encoding.UTF8.GetBytes(Answer(cycle, random.Next(16), random.Next(16), random.Next(16), random.Next(16)));
        switch (random.Next(10))
        {
            case 0:
                yield return good;
                break;
            case 1: // a byte flipped
                var flipped = (byte[])good.Clone();
                flipped[random.Next(flipped.Length - 1)] = (byte)random.Next(256);
                yield return flipped;
                break;
            case 2: // cut short, the rest of the line later
                int cut = random.Next(1, good.Length);
                yield return good[..cut];
                yield return good[cut..];
                break;
            case 3: // random bytes, ending a line
                var noise = new byte[random.Next(0, 200)];
                random.NextBytes(noise);
                yield return (byte[])[.. noise, (byte)'\n'];
                break;
            case 4:
                yield return ScriptedLink.Late;
                yield return good;
                break;
            case 5: // a field of another type
                string[] values = ["null", "true", "-1", "1e99", "\"x\"", "[]", "{}", "[[1,2,3]]", "2147483648"];
                string field = random.Next(2) == 0 ? "cycle" : "decisions";
                yield return System.Text.Encoding.UTF8.GetBytes($"{{\"type\":\"decisions\",\"cycle\":{cycle},\"{field}\":{values[random.Next(values.Length)]}}}\n");
                break;
            case 6: // a fault report, or an unknown fault kind
                yield return System.Text.Encoding.UTF8.GetBytes($"{{\"type\":\"decisions\",\"cycle\":{cycle},\"fault\":\"{(random.Next(2) == 0 ? "exception" : "gremlins")}\",\"message\":\"boom\\nline\"}}\n");
                break;
            case 7: // stray empty lines first
                yield return "\n\r\n"u8.ToArray();
                yield return good;
                break;
            case 8: // a line over the limit
                yield return System.Text.Encoding.UTF8.GetBytes(new string(' ', ProtocolLimits.ClientLineBytes + 1) + "\n");
                break;
            default: // deeply nested unknown field
                yield return System.Text.Encoding.UTF8.GetBytes($"{{\"deep\":{new string('[', 500)}{new string(']', 500)},\"type\":\"decisions\",\"cycle\":{cycle},\"decisions\":[[1,2],[3,4]]}}\n");
                break;
        }
    }

    private StrategyConnection Connect(ScriptedLink link, string? token)
    {
        int[] fish = [.. Enumerable.Range(0, _match.World.Fish.Length).Where(i => _match.World.Fish[i].Team == 0)];
        Assert.Equal(2, fish.Length);
        var assignment = new AssignmentMessage(1, 0, "", "match", fish, _match.World.Fish.Length, _match.World.Balls.Length, 0, 100, _match.World.Field.Length, _match.World.Field.Width, _match.World.Obstacles);
        return new StrategyConnection(link, assignment, TimeSpan.FromSeconds(1), TimeSpan.FromSeconds(1), token, _log.Add);
    }

    private MatchSnapshot Next()
    {
        _match.Step();
        return _match.Snapshot;
    }
}
