namespace URWPGSim2D.Server.Cli.Syntax;

/// <summary>
/// One word of a command's arguments as the parser classified it: an occurrence of a declared
/// option (with the value it took, if it takes one), or a positional word (an argument, or an
/// unknown option the command reports with a suggestion).
/// </summary>
/// <param name="Text">The word as typed: the option's name or alias, or the positional word.</param>
/// <param name="Option">The declared option, or null for a positional word.</param>
/// <param name="Value">The option's value; null for a flag, a positional word, or an option whose value is missing.</param>
internal readonly record struct CommandLineWord(string Text, Option? Option, string? Value)
{
    /// <summary>The option's name (its first name, e.g. <c>--help</c> for <c>-h</c>), or the positional word.</summary>
    public string Name => Option?.Name ?? Text;

    /// <summary>Whether this is an occurrence of a declared option.</summary>
    public bool IsOption => Option is not null;

    /// <summary>Whether this is an option that takes a value but was given none (the last word).</summary>
    public bool LacksValue => Option is not null && Value is null && CliSyntax.TakesValue(Option);
}
