using System.Diagnostics;
using System.Net.Sockets;
using System.Threading;
using URWPGSim2D.Protocol;

namespace URWPGSim2D.Server.Cli;

/// <summary>
/// <c>connect HOST:PORT SPEC [--token T] [--wait SECONDS]</c>: plays one team's strategy for a
/// server that waits for it (<c>run --strategy TEAM=remote:PORT</c>), from another process or
/// machine. SPEC is anything <c>--strategy TEAM=SPEC</c> takes; the strategy runs exactly as in a
/// strategy host (<see cref="StrategyClient"/>), with the original's API served as locally. It plays
/// every match the server gives the connection (a tournament's remote entrant), each with a fresh
/// instance of the strategy, and prints one line per match.
/// </summary>
internal sealed class ConnectCommand : ICliCommand
{
    /// <summary>Exit code: the server refused the client (wrong token, another version).</summary>
    public const int Refused = 6;

    /// <summary>Default <c>--wait</c>: how long to keep trying to reach the server, seconds.</summary>
    public const int DefaultWaitSeconds = 10;

    /// <inheritdoc/>
    public string Name => "connect";

    /// <inheritdoc/>
    public string Synopsis => $"{Name} {Line.Text}";

    /// <inheritdoc/>
    public string Summary => "Play one team's strategy for a server that waits for it (run --strategy TEAM=remote:PORT; docs/protocol.md).";

    /// <inheritdoc/>
    public Command Syntax { get; } = CliSyntax.Command("connect", "Play one team's strategy for a server that waits for it.", Line, HelpOption);

    private static readonly Option<bool> HelpOption = CliSyntax.Help();
    private static readonly Option<string> TokenOption = CliSyntax.Value("--token", "T", "the token the server was given (--remote-token)");
    private static readonly Option<string> WaitOption = CliSyntax.Value("--wait", "SECONDS", $"keep trying to reach the server this long (default {DefaultWaitSeconds})");

    private static readonly UsageLine Line = new(
        CliSyntax.Positional("HOST:PORT SPEC", "the server's address and the strategy", CliCompletions.Strategies),
        UsageLine.Optional(TokenOption),
        UsageLine.Optional(WaitOption));

    /// <inheritdoc/>
    public int Run(IReadOnlyList<CommandLineWord> words, CliConsole console)
    {
        if (words.Count == 1 && words[0].Option == HelpOption)
        {
            console.Out.Write(
                $"Usage: {CliApp.ProgramName} {Synopsis}\n\n" +
                "Connects to a server that waits for a remote team (run --strategy TEAM=remote:PORT) and plays the strategy\n" +
                "SPEC for it (a built-in name, .dll, .cs file or folder, as --strategy TEAM=SPEC) until the match ends; for a\n" +
                "tournament (--entrant NAME=remote:PORT) every match of the entrant, in turn, each with a fresh instance.\n" +
                Line.OptionTable(18) +
                "Exit codes: 0 the match (or every match) ended, 2 bad arguments, 3 the strategy cannot be loaded, 4 its constructor threw,\n" +
                "5 the server cannot be reached, broke the protocol or closed the connection, 6 the server refused the client.\n");
            return ExitCodes.Success;
        }

        var (host, port, spec, token, wait) = Parse(words);
        IStrategy strategy;
        try
        {
            strategy = StrategyResolver.Load(spec, console.ErrorLine, compileInThisProcess: true); // the team's own strategy on its own machine
        }
        catch (StrategyLoadException e)
        {
            foreach (string line in e.Lines)
            {
                console.ErrorLine(line);
            }

            return e is StrategyCreationException ? HostCommand.NotCreated : HostCommand.Unusable;
        }

        using var socket = Reach(host, port, wait, console);
        if (socket is null)
        {
            return HostCommand.Disconnected;
        }

        using var stream = new NetworkStream(socket, ownsSocket: false);
        var client = new StrategyClient(stream, stream);
        try
        {
            void Ended(EndMessage end)
            {
                console.Out.WriteLine(string.Create(CultureInfo.InvariantCulture, $"match ended after {end.Cycle} cycles: {string.Join(':', end.Goals)}, {end.Faults} fault(s) charged to this team"));
                console.Out.Flush();
            }

            switch (client.PlaySeries(strategy, before => Fresh(spec, before, console), token, Ended))
            {
                case StrategyClient.Ending.Ended:
                    return ExitCodes.Success;
                case StrategyClient.Ending.Refused:
                    console.ErrorLine("connect: the server refused the client: " + client.Error);
                    return Refused;
                default:
                    console.ErrorLine("connect: the server closed the connection before the end of the match");
                    return HostCommand.Disconnected;
            }
        }
        catch (ProtocolException e)
        {
            console.ErrorLine("connect: protocol: " + e.Message);
            return HostCommand.Disconnected;
        }
        catch (System.IO.IOException e)
        {
            console.ErrorLine("connect: the connection broke: " + e.Message);
            return HostCommand.Disconnected;
        }
    }

    // A fresh instance of the strategy for the next match; the one before when it can no longer be loaded (said on stderr).
    private static IStrategy Fresh(string spec, IStrategy before, CliConsole console)
    {
        try
        {
            return StrategyResolver.Load(spec, null, compileInThisProcess: true);
        }
        catch (StrategyLoadException e)
        {
            console.ErrorLine($"connect: {e.Message}; the next match plays on with the instance before");
            return before;
        }
    }

    // The server's socket, trying again every quarter second for up to `wait`; null (reported) when it cannot be reached.
    private static Socket? Reach(string host, int port, int wait, CliConsole console)
    {
        var clock = Stopwatch.StartNew();
        while (true)
        {
            var socket = new Socket(SocketType.Stream, ProtocolType.Tcp) { NoDelay = true };
            try
            {
                socket.Connect(host, port);
                return socket;
            }
            catch (SocketException e)
            {
                socket.Dispose();
                if (clock.Elapsed.TotalSeconds >= wait || e.SocketErrorCode is SocketError.HostNotFound or SocketError.NoData)
                {
                    console.ErrorLine($"connect: cannot reach {host}:{port.ToString(CultureInfo.InvariantCulture)}: {e.Message}");
                    return null;
                }

                Thread.Sleep(250);
            }
        }
    }

    private (string Host, int Port, string Spec, string? Token, int Wait) Parse(IReadOnlyList<CommandLineWord> words)
    {
        string? address = null, spec = null, token = null;
        int? wait = null;
        foreach (var word in words)
        {
            string a = word.Text;
            if (word.Option == TokenOption || word.Option == WaitOption)
            {
                string value = word.Value ?? throw Usage($"{a} needs a value");
                if (word.Option == TokenOption)
                {
                    token = token is null ? value : throw Usage("--token given twice");
                    if (value.Length == 0 || value.Length > ProtocolLimits.TextChars)
                    {
                        throw Usage($"--token must be 1..{ProtocolLimits.TextChars} characters, got {value.Length}");
                    }
                }
                else
                {
                    wait = wait is null && int.TryParse(value, NumberStyles.None, CultureInfo.InvariantCulture, out int w) && w <= 86_400
                        ? w : throw Usage($"--wait must be an integer 0..86400 (seconds), once, got {MessageText.Quote(value)}");
                }
            }
            else if (a.StartsWith('-'))
            {
                throw CliUsageException.UnknownOption("connect", a, Syntax, $"{CliApp.ProgramName} {Synopsis}");
            }
            else if (address is null)
            {
                address = a;
            }
            else
            {
                spec = spec is null ? a : throw Usage($"unexpected argument {MessageText.Quote(a)}");
            }
        }

        if (address is null || spec is null)
        {
            throw Usage("connect needs HOST:PORT and SPEC");
        }

        int colon = address.LastIndexOf(':');
        string host = colon > 0 ? address[..colon].Trim('[', ']') : "";
        if (host.Length == 0 || !int.TryParse(address.AsSpan(colon + 1), NumberStyles.None, CultureInfo.InvariantCulture, out int port) || port < 1 || port > 65535)
        {
            throw Usage($"HOST:PORT must be a host and a port 1..65535 (127.0.0.1:7000, [::1]:7000), got {MessageText.Quote(address)}");
        }

        return (host, port, spec, token, wait ?? DefaultWaitSeconds);
    }

    private CliUsageException Usage(string message) => new("connect: " + message, $"{CliApp.ProgramName} {Synopsis}");
}
