namespace URWPGSim2D.Protocol.Tests;

/// <summary>
/// <c>series</c>: a client that can play several matches on one connection says so in its hello, and a
/// server that keeps the connection says so in the assignment; either is absent unless it is true, so an
/// older peer sees exactly the messages it knew.
/// </summary>
public sealed class SeriesTests
{
    [Fact]
    public void Hello_and_assignment_say_series_only_when_it_is_true_and_read_it_back()
    {
        var writer = new MessageWriter();
        string plain = Encoding.UTF8.GetString(writer.Hello(1, "t", "x", packed: true));
        Assert.DoesNotContain("series", plain, StringComparison.Ordinal);
        Assert.False(MessageReader.ReadHello(Encoding.UTF8.GetBytes(plain.TrimEnd('\n'))).Series);
        string series = Encoding.UTF8.GetString(writer.Hello(1, "t", "x", packed: true, series: true));
        Assert.Contains("\"series\":true", series, StringComparison.Ordinal);
        var hello = MessageReader.ReadHello(Encoding.UTF8.GetBytes(series.TrimEnd('\n')));
        Assert.True(hello.Series && hello.Packed);
        Assert.Equal(("t", "x"), (hello.Token, hello.Name));

        var a = new AssignmentMessage(1, 0, "", "match", [0], 1, 1, 0, 100, 3000, 2000, []);
        Assert.DoesNotContain("series", Encoding.UTF8.GetString(writer.Assignment(a)), StringComparison.Ordinal);
        Assert.False(MessageReader.ReadAssignment(writer.Assignment(a)[..^1]).Series);
        Assert.True(MessageReader.ReadAssignment(writer.Assignment(a with { Series = true })[..^1]).Series);
    }

    [Fact]
    public void A_series_field_of_another_type_is_an_error()
    {
        var e = Assert.Throws<ProtocolException>(() => MessageReader.ReadHello("{\"type\":\"hello\",\"version\":1,\"series\":1}"u8));
        Assert.Contains("series", e.Message, StringComparison.Ordinal);
    }
}
