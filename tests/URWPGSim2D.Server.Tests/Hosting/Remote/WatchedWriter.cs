using System.Text.RegularExpressions;

namespace URWPGSim2D.Server.Tests.Hosting.Remote;

/// <summary>A server's standard error, read while it runs: it tells the port a remote team waits on.</summary>
internal sealed partial class WatchedWriter : TextWriter
{
    private readonly StringBuilder _text = new();
    private readonly ManualResetEventSlim _waiting = new();
    private readonly System.Collections.Generic.List<int> _ports = [];

    public override Encoding Encoding => Encoding.UTF8;

    public override void Write(char value)
    {
        lock (_text)
        {
            _text.Append(value);
            if (value == '\n' && Waiting().Match(LastLine()) is { Success: true } m)
            {
                int port = int.Parse(m.Groups[1].Value, System.Globalization.CultureInfo.InvariantCulture);
                if (_ports.Count == 0)
                {
                    Port = port;
                }

                _ports.Add(port);
                _waiting.Set();
                Monitor.PulseAll(_text);
            }
        }
    }

    /// <summary>The port of the first "waiting for a client" line.</summary>
    public int Port { get; private set; }

    /// <summary>Waits for the server to say it waits for a client (or gives up after a minute: the server failed).</summary>
    public int WaitForPort() => _waiting.Wait(TimeSpan.FromMinutes(1)) ? Port : throw new InvalidOperationException("the server never waited for a client: " + ToString());

    /// <summary>Waits until the server has said it waits for <paramref name="count"/> clients (or gives up after a minute: the server failed); the ports in the order said.</summary>
    public int[] WaitForPorts(int count)
    {
        lock (_text)
        {
            var until = DateTime.UtcNow + TimeSpan.FromMinutes(1);
            while (_ports.Count < count)
            {
                TimeSpan left = until - DateTime.UtcNow;
                if (left <= TimeSpan.Zero || !Monitor.Wait(_text, left))
                {
                    throw new InvalidOperationException($"the server did not wait for {count} clients: " + _text);
                }
            }

            return [.. _ports];
        }
    }

    // The text's last line (the one just ended), without its line break.
    private string LastLine()
    {
        int end = _text.Length - 1, start = end;
        while (start > 0 && _text[start - 1] != '\n')
        {
            start--;
        }

        return _text.ToString(start, end - start);
    }

    public override string ToString()
    {
        lock (_text)
        {
            return _text.ToString();
        }
    }

    [GeneratedRegex(@"waiting for a client on 127\.0\.0\.1:(\d+)")]
    private static partial Regex Waiting();
}
