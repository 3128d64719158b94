namespace URWPGSim2D.Protocol.Tests;

/// <summary>Framing: lines split across reads, CRLF, a partial last line, the length limit.</summary>
public class LineChannelTests
{
    /// <summary>A stream that hands out at most <c>chunk</c> bytes per read, to split lines anywhere.</summary>
    private sealed class Trickle(byte[] data, int chunk) : MemoryStream(data)
    {
        public override int Read(byte[] buffer, int offset, int count) => base.Read(buffer, offset, Math.Min(count, chunk));
    }

    [Theory]
    [InlineData(1)]
    [InlineData(3)]
    [InlineData(4096)]
    public void Lines_come_back_whole_however_the_stream_splits_them(int chunk)
    {
        string text = "{\"a\":1}\n\r\n{\"b\":\"" + new string('x', 40000) + "\"}\r\n{\"c\":3}\npartial";
        var channel = new LineChannel(new Trickle(Encoding.UTF8.GetBytes(text), chunk), Stream.Null, 65536);
        Assert.True(channel.TryReadLine(out var line));
        Assert.Equal("{\"a\":1}", Encoding.UTF8.GetString(line));
        Assert.True(channel.TryReadLine(out line));
        Assert.Equal("", Encoding.UTF8.GetString(line));
        Assert.True(channel.TryReadLine(out line));
        Assert.Equal(40008, line.Length);
        Assert.True(channel.TryReadLine(out line));
        Assert.Equal("{\"c\":3}", Encoding.UTF8.GetString(line));
        Assert.False(channel.TryReadLine(out _)); // the partial last line is dropped
    }

    [Fact]
    public void A_line_over_the_limit_is_refused()
    {
        var channel = new LineChannel(new MemoryStream(Encoding.UTF8.GetBytes(new string('x', 200) + "\n")), Stream.Null, 100);
        var e = Assert.Throws<ProtocolException>(() => channel.TryReadLine(out _));
        Assert.Equal("a line is longer than 100 bytes", e.Message);
    }

    [Fact]
    public void A_line_at_the_limit_is_read()
    {
        var channel = new LineChannel(new MemoryStream(Encoding.UTF8.GetBytes(new string('x', 100) + "\n")), Stream.Null, 100);
        Assert.True(channel.TryReadLine(out var line));
        Assert.Equal(100, line.Length);
    }

    [Fact]
    public void Written_lines_end_with_a_newline_and_nothing_else_is_accepted()
    {
        var output = new MemoryStream();
        var channel = new LineChannel(Stream.Null, output, 100);
        channel.WriteLine(new MessageWriter().Error("x"));
        Assert.Equal("{\"type\":\"error\",\"message\":\"x\"}\n", Encoding.UTF8.GetString(output.ToArray()));
        Assert.Throws<ArgumentException>(() => channel.WriteLine("{}"u8));
    }
}
