using System.Net.Sockets;

namespace URWPGSim2D.Server.Tests.Hosting.Remote;

/// <summary>
/// A remote client that disconnects is charged once, its fish stop, the match goes on, and a
/// client that connects again plays on from the next cycle. The test steps the match itself and
/// its scripted client answers over loopback TCP, so every step is determined.
/// </summary>
public sealed class ReconnectTests
{
    [Fact]
    public void A_client_that_disconnects_is_charged_once_and_may_connect_again()
    {
        var log = new System.Collections.Generic.List<string>();
        using var seat = new RemoteSeat(0, IPAddress.Loopback, 0, "k", TimeSpan.FromSeconds(30), l => { lock (log) { log.Add(l); } });
        var match = MatchBuilder.Build(DefaultScenario.Load(), [TeamStrategy.RemoteClient("remote", seat), null], cycles: 1000, strategyTimeoutMs: 20_000);
        var slot = match.Caller().Slots.Single(s => s.Team == 0);
        var remote = (RemoteStrategy)slot.Hosted!;

        // The first client answers cycles 0..2 with (3, 4) and goes away when it is sent cycle 3.
        var first = Client(seat, gear: 3, leaveAt: 3, out _);
        remote.WaitForClient();
        for (int i = 0; i < 3; i++)
        {
            match.Step();
        }

        Assert.All(slot.Fish, f => Assert.Equal(new Decision(3, 4), match.World.Fish[f].Decision));
        match.Step(); // cycle 3: the client has gone
        first.Join();
        Assert.Equal(1, slot.Disconnects);
        Assert.StartsWith("cycle 4: remote client disconnected: the client at 127.0.0.1:", slot.FirstFault, StringComparison.Ordinal);
        Assert.All(slot.Fish, f => Assert.Equal(Decision.Stop, match.World.Fish[f].Decision));
        match.Step(); // cycle 4: nobody there, nothing charged
        Assert.Equal(1, slot.Faults);

        // A second client connects (its hello waits in the socket) and plays on from cycle 5.
        var second = Client(seat, gear: 11, leaveAt: int.MaxValue, out var ended);
        ended.Connected.Wait();
        match.Step();
        Assert.All(slot.Fish, f => Assert.Equal(new Decision(11, 12), match.World.Fish[f].Decision));
        match.Step();
        URWPGSim2D.Engine.Matches.MatchLoop.StopStrategies(match);
        second.Join();
        Assert.Equal(1, slot.Faults);
        Assert.Equal("{\"type\":\"end\",\"cycle\":7,\"goals\":[0,0],\"faults\":1}", ended.Last);
        Assert.Contains(log, l => l.StartsWith("team 0 (remote): cycle 4: the client at 127.0.0.1:", StringComparison.Ordinal) && l.EndsWith("waiting for the client to connect again on " + seat.Address, StringComparison.Ordinal));
    }

    // What the scripted client saw.
    private sealed class Seen
    {
        public ManualResetEventSlim Connected { get; } = new();

        public string? Last { get; set; }
    }

    // A client on a thread: hello, then (gear, gear + 1) for every fish of every cycle until it is sent cycle `leaveAt`.
    private static Thread Client(RemoteSeat seat, int gear, int leaveAt, out Seen seen)
    {
        var socket = new Socket(SocketType.Stream, ProtocolType.Tcp) { NoDelay = true };
        socket.Connect(seat.EndPoint);
        var stream = new NetworkStream(socket, ownsSocket: true);
        var writer = new StreamWriter(stream, new UTF8Encoding(false)) { AutoFlush = true, NewLine = "\n" };
        writer.WriteLine("{\"type\":\"hello\",\"version\":1,\"token\":\"k\"}");
        var s = seen = new Seen();
        s.Connected.Set();
        var thread = new Thread(() =>
        {
            using var reader = new StreamReader(stream, new UTF8Encoding(false));
            int fish = 0;
            while (reader.ReadLine() is { } line)
            {
                s.Last = line;
                if (line.StartsWith("{\"type\":\"assignment\"", StringComparison.Ordinal))
                {
                    fish = System.Text.Json.JsonDocument.Parse(line).RootElement.GetProperty("fish").GetArrayLength();
                }
                else if (line.StartsWith("{\"type\":\"cycle\"", StringComparison.Ordinal))
                {
                    int cycle = System.Text.Json.JsonDocument.Parse(line).RootElement.GetProperty("cycle").GetInt32();
                    if (cycle == leaveAt)
                    {
                        break;
                    }

                    writer.WriteLine($"{{\"type\":\"decisions\",\"cycle\":{cycle},\"decisions\":[{string.Join(',', Enumerable.Repeat($"[{gear},{gear + 1}]", fish))}]}}");
                }
            }

            writer.Dispose();
        }) { IsBackground = true };
        thread.Start();
        return thread;
    }
}
