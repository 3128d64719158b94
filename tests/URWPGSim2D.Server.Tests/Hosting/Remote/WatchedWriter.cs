using System;
using System.IO;
using System.Text;
using System.Text.RegularExpressions;
using System.Threading;

namespace URWPGSim2D.Server.Tests.Hosting.Remote;

/// <summary>A server's standard error, read while it runs: it tells the port a remote team waits on.</summary>
internal sealed partial class WatchedWriter : TextWriter
{
    private readonly StringBuilder _text = new();
    private readonly ManualResetEventSlim _waiting = new();

    public override Encoding Encoding => Encoding.UTF8;

    public override void Write(char value)
    {
        lock (_text)
        {
            _text.Append(value);
            if (value == '\n' && Waiting().Match(_text.ToString()) is { Success: true } m)
            {
                Port = int.Parse(m.Groups[1].Value, System.Globalization.CultureInfo.InvariantCulture);
                _waiting.Set();
            }
        }
    }

    /// <summary>The port of the first "waiting for a client" line.</summary>
    public int Port { get; private set; }

    /// <summary>Waits for the server to say it waits for a client (or gives up after a minute: the server failed).</summary>
    public int WaitForPort() => _waiting.Wait(TimeSpan.FromMinutes(1)) ? Port : throw new InvalidOperationException("the server never waited for a client: " + ToString());

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
