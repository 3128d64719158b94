namespace URWPGSim2D.Server.Cli;

/// <summary>
/// <c>completion bash|zsh|pwsh</c>: prints the script that gives the shell tab completion of the
/// program's commands, options and values. The script asks the program itself
/// (<see cref="ShellCompletion"/>), so completion always matches the installed version.
/// </summary>
internal sealed class CompletionCommand : ICliCommand
{
    private static readonly Option<bool> HelpOption = CliSyntax.Help();

    /// <summary>The shells with a script.</summary>
    public static IReadOnlyList<string> Shells { get; } = ["bash", "zsh", "pwsh"];

    /// <inheritdoc/>
    public string Name => "completion";

    /// <inheritdoc/>
    public string Synopsis => $"{Name} {Line.Text}";

    /// <inheritdoc/>
    public string Summary => "Print the shell script that completes commands, options, items and strategies on Tab.";

    /// <inheritdoc/>
    public Command Syntax { get; } = CliSyntax.Command("completion", "Print the shell's completion script.", Line, HelpOption);

    private static readonly UsageLine Line = new(CliSyntax.Positional(string.Join('|', Shells), "bash, zsh or pwsh", CliCompletions.Fixed([.. Shells])));

    private string Usage => $"{CliApp.ProgramName} {Synopsis}";

    /// <inheritdoc/>
    public int Run(IReadOnlyList<CommandLineWord> words, CliConsole console)
    {
        if (words.Count == 1 && words[0].Option == HelpOption)
        {
            console.Out.Write(
                $"Usage: {Usage}\n\n" +
                "Prints a script that completes the commands, options, item names (with the Chinese names),\n" +
                "strategy names and file names of 'urwpgsim2d' when you press Tab. Install it once:\n" +
                "  bash:  urwpgsim2d completion bash >> ~/.bashrc\n" +
                "  zsh:   urwpgsim2d completion zsh >> ~/.zshrc\n" +
                "  pwsh:  urwpgsim2d completion pwsh >> $PROFILE\n" +
                "Then open a new shell. Details: docs/cli.md.\n");
            return ExitCodes.Success;
        }

        if (words.Count > 0 && words[0].Text.StartsWith('-'))
        {
            throw CliUsageException.UnknownOption(Name, words[0].Text, Syntax, Usage);
        }

        if (words.Count != 1)
        {
            throw new CliUsageException($"completion: expected one SHELL (bash, zsh or pwsh), got {words.Count}", Usage);
        }

        console.Out.Write(words[0].Text switch
        {
            "bash" => CompletionScripts.Bash,
            "zsh" => CompletionScripts.Zsh,
            "pwsh" => CompletionScripts.PowerShell,
            _ => throw new CliUsageException($"completion: SHELL must be bash, zsh or pwsh, got {MessageText.Quote(words[0].Text)}", Usage),
        });
        return ExitCodes.Success;
    }
}
