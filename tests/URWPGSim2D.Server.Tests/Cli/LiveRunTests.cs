using System.Net.Sockets;
using System.Text.RegularExpressions;
using URWPGSim2D.Engine.Matches;

namespace URWPGSim2D.Server.Tests.Cli;

/// <summary>
/// <c>run --live</c>'s summary: printed as soon as the match ends, while the page is still
/// served, once; its real-time figure is the match's own wall time, so a match played at real
/// speed (or X times it) never claims more.
/// </summary>
public sealed partial class LiveRunTests
{
    [Fact]
    public async Task TheSummaryComesWhenTheMatchEndsWithTrueRealTimeFigures()
    {
        // 20 cycles at --speed 10: a cycle every 10 ms, so the match takes at least 19 intervals
        // (the player never plays a cycle before its deadline) and cannot be faster than about 10x.
        var options = RunOptions.Parse(["--live", "--speed", "10", "--cycles", "20", "--port", FreePort().ToString(CultureInfo.InvariantCulture)]);
        var output = new SignallingWriter("match over");
        var errors = new StringWriter();
        var console = new CliConsole(new StringReader(string.Empty), output, TextWriter.Synchronized(errors));
        using var stop = new CancellationTokenSource();
        var served = Task.Run(() => LiveRun.Serve(options, DefaultScenario.Load(), new TeamStrategy?[2], console, stop.Token, _ => { }));

        Assert.True(await Task.WhenAny(output.Seen, served, Task.Delay(60_000)) == output.Seen, "no summary when the match ended: " + output + " / stderr: " + errors);
        Assert.False(served.IsCompleted, "the page is still served after the match");
        string atEnd = output.ToString();
        var first = LiveLine().Match(atEnd.Split('\n')[0]);
        Assert.True(first.Success, atEnd);
        double wall = double.Parse(first.Groups[1].Value, CultureInfo.InvariantCulture);
        double pace = double.Parse(first.Groups[2].Value, CultureInfo.InvariantCulture);
        Assert.InRange(wall, 0.2, double.MaxValue); // 19 intervals of 10 ms, rounded to 0.1 s
        Assert.InRange(pace, 0.1, (10.0 * 20 / 19) + 0.05);
        Assert.EndsWith("\nmatch over: the page stays up (restart there plays it again; Ctrl+C to stop)\n", atEnd, StringComparison.Ordinal);

        stop.Cancel();
        Assert.Equal(0, await served);
        Assert.Equal(atEnd, output.ToString()); // once: nothing more at Ctrl+C
    }

    [Fact]
    public void TheLiveRealTimeFigureIsSimulatedTimeOverTheMatchsWallTime()
    {
        // A 3-minute match played at real speed took 180 s of wall time, 0.5 s of it computing.
        var match = new MatchSettings(DefaultScenario.Load(), 1800, 1).Build();
        using (var loop = new MatchLoop(match, 1800, null, null))
        {
            loop.Play();
        }

        MatchLoop.StopStrategies(match);
        string first = MatchSummary.FormatLive(match, TimeSpan.FromSeconds(180), TimeSpan.FromSeconds(0.5)).Split('\n')[0];
        Assert.Equal("match: 1800 cycles, 180.0 s simulated, played live in 180.0 s wall time (1.0x real time, 277.78 us of computing per cycle), seed 1", first);
        Assert.DoesNotContain("real time", MatchSummary.FormatLive(match, TimeSpan.Zero, TimeSpan.Zero).Split('\n')[0], StringComparison.Ordinal);
    }

    private static int _nextPort;

    /// <summary>
    /// A free port for a live server no other test takes: from this test process's own block of 100
    /// below the kernel's ephemeral range (so no outgoing connection and no other test process gets
    /// it meanwhile), each handed out once, checked free.
    /// </summary>
    internal static int FreePort()
    {
        int block = 20_000 + (Environment.ProcessId % 120 * 100);
        for (int attempt = 0; attempt < 100; attempt++)
        {
            int port = block + (Interlocked.Increment(ref _nextPort) % 100);
            try
            {
                var probe = new TcpListener(IPAddress.Loopback, port);
                probe.Start();
                probe.Stop();
                return port;
            }
            catch (SocketException)
            {
                // taken by something else on the machine: the next one
            }
        }

        throw new InvalidOperationException("no free port in this test process's block");
    }

    [GeneratedRegex(@"^match: 20 cycles, 2\.0 s simulated, played live in ([0-9]+\.[0-9]) s wall time \(([0-9]+\.[0-9])x real time, [0-9]+\.[0-9]{2} us of computing per cycle\), seed 1$")]
    private static partial Regex LiveLine();

    // Standard output as the server writes it, read safely from the test's thread; Seen completes once the text holds a marker.
    internal sealed class SignallingWriter(string marker) : TextWriter
    {
        private readonly StringBuilder _text = new();
        private readonly TaskCompletionSource _seen = new(TaskCreationOptions.RunContinuationsAsynchronously);

        public Task Seen => _seen.Task;

        public override Encoding Encoding => Encoding.UTF8;

        public override void Write(char value) => Write(value.ToString());

        public override void Write(string? value)
        {
            lock (_text)
            {
                _text.Append(value);
                if (_text.ToString().Contains(marker, StringComparison.Ordinal))
                {
                    _seen.TrySetResult();
                }
            }
        }

        public override string ToString()
        {
            lock (_text)
            {
                return _text.ToString();
            }
        }
    }
}
