using URWPGSim2D.Protocol;

namespace URWPGSim2D.Server.Cli;

/// <summary>
/// <c>host SPEC</c>: the strategy host. Loads one team's strategy and plays it for the server over
/// standard input and output with the strategy protocol (docs/protocol.md); <c>run</c> starts one
/// per team and match, in a sandbox where it can. What the strategy writes to the console goes to
/// standard error, so it cannot garble the protocol.
/// </summary>
internal sealed class HostCommand : ICliCommand
{
    /// <summary>Exit code: the strategy cannot be loaded (not found, not a strategy, does not compile).</summary>
    public const int Unusable = 3;

    /// <summary>Exit code: the strategy's constructor or static constructor threw.</summary>
    public const int NotCreated = 4;

    /// <summary>Exit code: the server broke the protocol or closed the connection before the end.</summary>
    public const int Disconnected = 5;

    /// <inheritdoc/>
    public string Name => "host";

    /// <inheritdoc/>
    public string Synopsis => $"{Name} {Line.Text}";

    /// <inheritdoc/>
    public string Summary => "Play one team's strategy for 'run' over standard input/output (the strategy host; docs/protocol.md).";

    /// <inheritdoc/>
    public Command Syntax { get; } = CliSyntax.Command("host", "Play one team's strategy over standard input/output.", Line, HelpOption);

    private static readonly Option<bool> HelpOption = CliSyntax.Help();

    private static readonly UsageLine Line = new(CliSyntax.Positional("SPEC", "the strategy", CliCompletions.Strategies));

    /// <inheritdoc/>
    public int Run(IReadOnlyList<CommandLineWord> words, CliConsole console)
    {
        if (words.Count == 1 && words[0].Option == HelpOption)
        {
            console.Out.Write(
                $"Usage: {CliApp.ProgramName} host SPEC\n\n" +
                "Loads the strategy SPEC (a .dll, .cs file or folder, as --strategy TEAM=SPEC) and plays it over standard\n" +
                "input and output with the strategy protocol (docs/protocol.md). 'run' starts one host per team and match;\n" +
                "exit codes: 0 the match ended, 3 the strategy cannot be loaded, 4 its constructor threw, 5 the server\n" +
                "broke the protocol or closed the connection. SPEC '-' is a pre-started host: it reads 'CPU-SECONDS SPEC'\n" +
                "from its first line of standard input, limits its CPU time to it and plays as 'host SPEC'.\n");
            return ExitCodes.Success;
        }

        if (words.Count >= 1 && words[0].Text.StartsWith('-') && words[0].Text != HostProcess.WaitingSpec)
        {
            throw CliUsageException.UnknownOption("host", words[0].Text, Syntax, $"{CliApp.ProgramName} {Synopsis}");
        }

        if (words.Count != 1)
        {
            throw new CliUsageException("host needs exactly one SPEC", $"{CliApp.ProgramName} {Synopsis}");
        }

        // The protocol owns the process's standard streams; the strategy's console goes to stderr.
        var fromServer = Console.OpenStandardInput();
        var toServer = Console.OpenStandardOutput();
        Console.SetIn(System.IO.TextReader.Null);
        Console.SetOut(Console.Error);
        string? spec = words[0].Text;
        if (spec == HostProcess.WaitingSpec)
        {
            // A pre-started host: warm up, then wait for the strategy's line.
            HostWarmUp.Run();
            spec = HostWarmUp.ReadStrategy(fromServer);
            if (spec is null)
            {
                return Disconnected;
            }
        }

        IStrategy strategy;
        try
        {
            strategy = StrategyResolver.Load(spec, compileInThisProcess: true); // the host is the sandbox
        }
        catch (StrategyLoadException e)
        {
            console.ErrorLine(e.Message);
            return e is StrategyCreationException ? NotCreated : Unusable;
        }

        // A host runs one strategy: the CPU time of all its threads counts against the deadline.
        var client = new StrategyClient(fromServer, toServer);
        try
        {
            return client.Play(strategy, token: null) == StrategyClient.Ending.Ended ? ExitCodes.Success : Disconnected;
        }
        catch (ProtocolException e)
        {
            console.ErrorLine("protocol: " + e.Message);
            return Disconnected;
        }
    }
}
