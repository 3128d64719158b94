using System.Runtime.InteropServices;
using System.Threading;
using URWPGSim2D.Engine.Matches;
using URWPGSim2D.Engine.Scenario;
using URWPGSim2D.Engine.Simulation;
using URWPGSim2D.Viewer;

namespace URWPGSim2D.Server.Cli;

/// <summary>
/// <c>run --live</c>: serves the viewer on <c>http://HOST:PORT/</c> and plays the match in real
/// time (× <c>--speed</c>) while any number of browsers watch, pause, step or restart it. When the
/// match is over its summary is printed at once and the page is served on (a restart plays the
/// match again, and its summary follows when it ends); Ctrl+C (or SIGTERM) ends the server, and a
/// match it interrupts gets its summary then. A port that cannot be used is one line on stderr and
/// exit code 2, before anything is played. With <c>--strategies DIR</c> the page has a control board
/// (<see cref="LiveBoard"/>) that chooses what the next match plays. On an address other machines
/// can reach (<c>--host</c> other than loopback) the page only watches unless it holds the control
/// token printed at start (the <c>control:</c> link), and the banner names the addresses viewers
/// open (every address of this machine for <c>--host 0.0.0.0</c>). A remote team's client is waited
/// for before the first match, as <c>run</c> waits (every remote address is said first); a restarted
/// match takes a client that plays a series at once, or waits for one and plays on without it after
/// <c>--remote-wait</c> (a client may connect at any cycle).
/// </summary>
internal static class LiveRun
{
    /// <summary>Runs the live view until Ctrl+C; returns the exit code.</summary>
    public static int Run(RunOptions options, ScenarioDefinition scenario, TeamStrategy?[] teams, CliConsole console)
    {
        using var stop = new CancellationTokenSource();
        ConsoleCancelEventHandler onCancel = (_, e) =>
        {
            e.Cancel = true;
            stop.Cancel();
        };
        Console.CancelKeyPress += onCancel;
        using var onTerm = PosixSignalRegistration.Create(PosixSignal.SIGTERM, c =>
        {
            c.Cancel = true;
            stop.Cancel();
        });
        try
        {
            return Serve(options, scenario, teams, console, stop.Token, url => console.Out.WriteLine($"live view: {url} (Ctrl+C to stop)"));
        }
        finally
        {
            Console.CancelKeyPress -= onCancel;
        }
    }

    /// <summary>Serves the live view until <paramref name="stop"/> is cancelled; prints a match's summary when it ends, or when <paramref name="stop"/> interrupts it.</summary>
    /// <param name="options">The run options (<c>--live</c> and its settings).</param>
    /// <param name="scenario">The scene.</param>
    /// <param name="teams">The loaded team strategies of the first match.</param>
    /// <param name="console">Where the summary and errors go.</param>
    /// <param name="stop">Ends the match and the server.</param>
    /// <param name="listening">Told the address once the server listens.</param>
    public static int Serve(RunOptions options, ScenarioDefinition scenario, TeamStrategy?[] teams, CliConsole console, CancellationToken stop, Action<string> listening)
    {
        bool first = true;
        MatchSettings Default()
        {
            var t = first ? teams : Reload(options, teams);
            first = false;
            return RunCommand.Settings(options, scenario, t);
        }

        var board = options.StrategiesFolder is null ? null : new LiveBoard(options, scenario, teams, console);
        var feed = new LiveFeed();
        Func<MatchSettings> next = board is null ? Default : board.Next;
        bool built = false;
        (Match, int) Build()
        {
            var settings = next();
            var match = settings.Build();
            try
            {
                match.Caller().ConnectRemoteTeams();
            }
            catch (RemoteWaitException e) when (built)
            {
                console.ErrorLine($"{e.Message}; the match plays on, and the client may connect at any cycle");
            }
            catch (RemoteWaitException)
            {
                match.Teams.Stop();
                throw;
            }

            built = true;
            return (match, settings.Cycles);
        }

        LiveMatch player;
        try
        {
            player = new LiveMatch(Build, options.Speed, options.Paused, feed);
        }
        catch (RemoteWaitException e)
        {
            console.ErrorLine(e.Message);
            return ExitCodes.BadInput;
        }

        LiveReply Control(string action, System.Collections.Specialized.NameValueCollection query) =>
            board?.Control(action, query, player.Start, player.Restart)
            ?? (player.Control(action) ? LiveReply.Done
                : board is null ? new LiveReply(400, "unknown action (pause, resume, step or restart)")
                : LiveReply.Refused($"unknown action {Engine.Messages.MessageText.Quote(action)} (pause, resume, step, restart, start or recompile)"));

        Match? summarised = null; // the last match whose summary is printed (on the playing thread, which is this one)
        player.Ended = ended =>
        {
            console.Out.Write(MatchSummary.FormatLive(ended, player.Played, player.Busy));
            MatchLoop.StopStrategies(ended); // the strategies are told the end now (a remote client that plays a series is kept for a restart)
            console.Out.Write("match over: the page stays up (restart there plays it again; Ctrl+C to stop)\n");
            console.Out.Flush();
            summarised = ended;
        };
        using var server = Open(options.Host, options.Port, feed, Control, board is null ? null : board.Json, console, listening);
        if (server is null)
        {
            MatchLoop.StopStrategies(player.Match);
            return ExitCodes.BadInput;
        }

        player.Run(stop);
        server.Stop();
        var match = player.Match;
        MatchLoop.StopStrategies(match);
        if (!ReferenceEquals(match, summarised))
        {
            console.Out.Write(MatchSummary.FormatLive(match, player.Played, player.Busy)); // interrupted: the cycles played
        }

        return ExitCodes.Success;
    }

    /// <summary>
    /// Starts the live page's server on <paramref name="host"/>:<paramref name="port"/> and prints its
    /// banner: on loopback the address (<paramref name="listening"/>); on an address other machines can
    /// reach, the addresses viewers open and the <c>control:</c> link with the control token made now
    /// (the other viewers only watch). Null, with one line on stderr, when the port cannot be used.
    /// </summary>
    /// <param name="host">The address to listen on (<c>--host</c>).</param>
    /// <param name="port">The port (<c>--port</c>).</param>
    /// <param name="feed">What the page shows.</param>
    /// <param name="control">The control actions.</param>
    /// <param name="board">The control board's state, or null.</param>
    /// <param name="console">Where the banner goes.</param>
    /// <param name="listening">Told the first address.</param>
    /// <param name="controls">What the control link can do, for the banner.</param>
    public static LiveServer? Open(string host, int port, LiveFeed feed, Func<string, System.Collections.Specialized.NameValueCollection, LiveReply> control, Func<string>? board, CliConsole console, Action<string> listening, string controls = "pause, restart and start matches")
    {
        string? token = IsLoopback(host) ? null : Convert.ToHexStringLower(System.Security.Cryptography.RandomNumberGenerator.GetBytes(16));
        var server = new LiveServer(host, port, feed, control, board, token);
        try
        {
            server.Start();
        }
        catch (LiveServerException e)
        {
            server.Dispose();
            console.ErrorLine($"--port {port}: {e.Message}");
            return null;
        }

        if (token is null)
        {
            listening(server.Url);
        }
        else
        {
            var addresses = ViewerAddresses(host, port, server.Url);
            listening(addresses[0]);
            for (int i = 1; i < addresses.Count; i++)
            {
                console.Out.WriteLine($"live view also: {addresses[i]}");
            }

            string home = host is "*" or "+" or "0.0.0.0" ? $"http://127.0.0.1:{port}/" : server.Url;
            console.Out.WriteLine($"control: {home}?token={token} (this link alone can {controls}: keep it to yourself; the addresses above only watch)");
        }

        console.Out.Flush();
        return server;
    }

    /// <summary>Whether a <c>--host</c> value is this machine alone (no other machine can reach it).</summary>
    /// <param name="host">The value.</param>
    public static bool IsLoopback(string host) =>
        host.Equals("localhost", StringComparison.OrdinalIgnoreCase)
        || (System.Net.IPAddress.TryParse(host.Trim('[', ']'), out var address) && System.Net.IPAddress.IsLoopback(address));

    // The addresses viewers on other machines open: for every interface (0.0.0.0), each IPv4 address of
    // an interface that is up, or the machine's name when it has none; else the address listened on.
    private static System.Collections.Generic.List<string> ViewerAddresses(string host, int port, string url)
    {
        var addresses = new System.Collections.Generic.List<string>();
        if (host is not ("*" or "+" or "0.0.0.0"))
        {
            addresses.Add(url);
            return addresses;
        }

        try
        {
            foreach (var network in System.Net.NetworkInformation.NetworkInterface.GetAllNetworkInterfaces())
            {
                if (network.OperationalStatus != System.Net.NetworkInformation.OperationalStatus.Up
                    || network.NetworkInterfaceType == System.Net.NetworkInformation.NetworkInterfaceType.Loopback)
                {
                    continue;
                }

                foreach (var unicast in network.GetIPProperties().UnicastAddresses)
                {
                    if (unicast.Address.AddressFamily == System.Net.Sockets.AddressFamily.InterNetwork && !System.Net.IPAddress.IsLoopback(unicast.Address))
                    {
                        addresses.Add($"http://{unicast.Address}:{port}/");
                    }
                }
            }
        }
        catch (System.Net.NetworkInformation.NetworkInformationException)
        {
            // No interfaces to list: the machine's name below.
        }

        if (addresses.Count == 0)
        {
            addresses.Add($"http://{System.Net.Dns.GetHostName()}:{port}/");
        }

        return addresses;
    }

    // A restart plays with freshly loaded strategies (their state starts over too).
    private static TeamStrategy?[] Reload(RunOptions options, TeamStrategy?[] teams)
    {
        try
        {
            return RunCommand.LoadTeams(options, seats: teams);
        }
        catch (Hosting.StrategyLoadException)
        {
            return teams; // the assembly vanished since the start: keep the loaded strategies
        }
    }
}
