namespace URWPGSim2D.Server.Cli;

/// <summary>
/// <c>inspect-dll FILE</c>: what a strategy DLL is — its name, framework, architecture, strategy API,
/// team name, the items its code mentions, its references and what stands for each here — and whether
/// <c>run</c> will load it, listing every missing type and member when it will not (exit 2). None of the
/// DLL's code runs (<see cref="StrategyInspection"/>).
/// </summary>
internal sealed class InspectDllCommand : ICliCommand
{
    private static readonly Option<bool> HelpOption = CliSyntax.Help();

    private static readonly UsageLine Line = new(CliSyntax.Positional("FILE", "the strategy DLL", CliCompletions.Paths));

    private static string Usage => "inspect-dll " + Line.Text;

    /// <inheritdoc/>
    public string Name => "inspect-dll";

    /// <inheritdoc/>
    public string Synopsis => Usage;

    /// <inheritdoc/>
    public string Summary => "Tell what a strategy DLL is (framework, architecture, API, team name, items, references) and whether it will load.";

    /// <inheritdoc/>
    public Command Syntax { get; } = CliSyntax.Command("inspect-dll", "Tell what a strategy DLL is and whether it will load.", Line, HelpOption);

    /// <inheritdoc/>
    public int Run(IReadOnlyList<CommandLineWord> words, CliConsole console)
    {
        if (words.Count == 1 && words[0].Option == HelpOption)
        {
            console.Out.Write(
                $"Usage: {CliApp.ProgramName} {Usage}\n\n" +
                "Reads the strategy DLL FILE (built for this server or for the original simulator) and prints what it is:\n" +
                "its assembly, SHA-256, framework, architecture, strategy API, strategy class, team name (when its code\n" +
                "returns a constant), the items its code mentions and what stands here for each assembly it references.\n" +
                "Then it loads the DLL as 'run' does, running none of its code: exit 0 when it will load, 2 when it will\n" +
                "not, with every missing type and member listed. More: docs/strategies.md.\n");
            return ExitCodes.Success;
        }

        string file = FileArgument.Parse("inspect-dll", words, Syntax, $"{CliApp.ProgramName} {Usage}");
        if (file == InputText.StandardInput)
        {
            throw new CliUsageException("inspect-dll: FILE must be a file, not - (standard input)", $"{CliApp.ProgramName} {Usage}");
        }

        StrategyInspection inspection;
        try
        {
            inspection = StrategyInspection.Of(file);
        }
        catch (StrategyLoadException e)
        {
            console.ErrorLine("inspect-dll: " + e.Message);
            return ExitCodes.BadInput;
        }

        console.Out.Write(Format(inspection));
        return inspection.Loads ? ExitCodes.Success : ExitCodes.BadInput;
    }

    /// <summary>The report as printed.</summary>
    /// <param name="inspection">What was found.</param>
    public static string Format(StrategyInspection inspection)
    {
        var text = new StringBuilder();
        text.Append("file: ").Append(inspection.File).Append('\n');
        text.Append("assembly: ").Append(inspection.Assembly).Append('\n');
        text.Append("sha-256: ").Append(inspection.Sha256).Append('\n');
        text.Append("framework: ").Append(inspection.Framework).Append('\n');
        text.Append("architecture: ").Append(inspection.Architecture).Append('\n');
        text.Append("strategy API: ").Append(inspection.Api).Append('\n');
        text.Append("built for the original: ").Append(inspection.Original ? "yes (retargeted to the compatibility assembly when it loads)" : "no").Append('\n');
        text.Append("strategy class: ").Append(inspection.StrategyClass ?? "-").Append('\n');
        text.Append("team name: ").Append(inspection.TeamName ?? "- (not a constant in its code)").Append('\n');
        text.Append("items its code mentions: ").Append(inspection.Items.Count == 0 ? "none found" : string.Join("; ", inspection.Items)).Append('\n');
        text.Append("references:\n");
        foreach (string reference in inspection.References)
        {
            text.Append("  ").Append(reference).Append('\n');
        }

        if (inspection.Loads)
        {
            text.Append("loads: yes\n");
        }
        else
        {
            text.Append("loads: no: ").Append(inspection.Refusal).Append('\n');
            if (inspection.Missing.Count > 0)
            {
                text.Append("missing:\n");
                foreach (string missing in inspection.Missing)
                {
                    text.Append("  ").Append(missing).Append('\n');
                }
            }
        }

        return text.ToString();
    }
}
