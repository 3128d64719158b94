using System.CommandLine.Completions;

namespace URWPGSim2D.Server.Cli.Syntax;

/// <summary>
/// How the commands declare their options and arguments to System.CommandLine: once, in each
/// command's syntax, the single source of option names for parsing, "did you mean" hints and shell
/// completion. Every value option takes exactly the next word, whatever it looks like
/// (<c>--sbatch-arg --mem=2G</c>); flags take none.
/// </summary>
internal static class CliSyntax
{
    /// <summary>
    /// The parser's settings: no response files (<c>@FILE</c> is an ordinary argument) and no
    /// bundling of short options.
    /// </summary>
    public static ParserConfiguration Parser { get; } = new()
    {
        ResponseFileTokenReplacer = null,
        EnablePosixBundling = false,
    };

    /// <summary>An option without a value, e.g. <c>--force</c>.</summary>
    /// <param name="name">The option's name.</param>
    /// <param name="description">What it does, one line.</param>
    public static Option<bool> Flag(string name, string description) =>
        new(name) { Arity = ArgumentArity.Zero, Description = description };

    /// <summary><c>--help</c> (alias <c>-h</c>): the command's help.</summary>
    public static Option<bool> Help() =>
        new("--help", "-h") { Arity = ArgumentArity.Zero, Description = "Show this command's help." };

    /// <summary>An option that takes the next word as its value, given at most once.</summary>
    /// <param name="name">The option's name.</param>
    /// <param name="valueName">The value's name in usage text, e.g. <c>FILE</c>.</param>
    /// <param name="description">What it does, one line.</param>
    /// <param name="completions">Completions of its value (see <see cref="CliCompletions"/>), or null for none.</param>
    public static Option<string> Value(string name, string valueName, string description, Func<CompletionContext, IEnumerable<CompletionItem>>? completions = null)
    {
        var option = new Option<string>(name) { Arity = ArgumentArity.ExactlyOne, HelpName = valueName, Description = description };
        if (completions is not null)
        {
            option.CompletionSources.Add(completions);
        }

        return option;
    }

    /// <summary>An option that takes the next word as its value and may be given again (each time one value).</summary>
    /// <param name="name">The option's name.</param>
    /// <param name="valueName">The value's name in usage text.</param>
    /// <param name="description">What it does, one line.</param>
    /// <param name="completions">Completions of its value, or null for none.</param>
    public static Option<string[]> Repeated(string name, string valueName, string description, Func<CompletionContext, IEnumerable<CompletionItem>>? completions = null)
    {
        var option = new Option<string[]>(name) { Arity = ArgumentArity.ExactlyOne, AllowMultipleArgumentsPerToken = false, HelpName = valueName, Description = description };
        if (completions is not null)
        {
            option.CompletionSources.Add(completions);
        }

        return option;
    }

    /// <summary>The positional words of a command (any number; the command checks how many).</summary>
    /// <param name="name">Their name in usage text, e.g. <c>FILE</c>.</param>
    /// <param name="description">What they are.</param>
    /// <param name="completions">Completions, or null for none.</param>
    public static Argument<string[]> Positional(string name, string description, Func<CompletionContext, IEnumerable<CompletionItem>>? completions = null)
    {
        var argument = new Argument<string[]>(name) { Arity = ArgumentArity.ZeroOrMore, Description = description };
        if (completions is not null)
        {
            argument.CompletionSources.Add(completions);
        }

        return argument;
    }

    /// <summary>A command with the given options and positional words.</summary>
    /// <param name="name">The command's name.</param>
    /// <param name="description">Its summary.</param>
    /// <param name="symbols">Its options and arguments, in the order its help names them.</param>
    public static Command Command(string name, string description, params Symbol[] symbols)
    {
        var command = new Command(name, description);
        foreach (Symbol symbol in symbols)
        {
            switch (symbol)
            {
                case Option option: command.Options.Add(option); break;
                case Argument argument: command.Arguments.Add(argument); break;
                default: throw new ArgumentException($"not an option or argument: {symbol.Name}", nameof(symbols));
            }
        }

        return command;
    }

    /// <summary>A command with the options and arguments of its usage line, and <c>--help</c>.</summary>
    /// <param name="name">The command's name.</param>
    /// <param name="description">Its summary.</param>
    /// <param name="usage">Its usage line, which declares its options and arguments.</param>
    /// <param name="help">Its <c>--help</c> option.</param>
    public static Command Command(string name, string description, UsageLine usage, Option<bool> help)
    {
        ArgumentNullException.ThrowIfNull(usage);
        return Command(name, description, [.. usage.Symbols, help]);
    }

    /// <summary>Whether <paramref name="option"/> takes a value.</summary>
    public static bool TakesValue(Option option) => option.Arity.MaximumNumberOfValues > 0;

    /// <summary>
    /// The long option names of <paramref name="command"/> (<c>--word</c>, names and aliases), the
    /// source of "did you mean" hints.
    /// </summary>
    public static IReadOnlyList<string> LongNames(Command command) =>
        [.. command.Options.SelectMany(o => o.Aliases.Prepend(o.Name)).Where(n => n.StartsWith("--", StringComparison.Ordinal)).Distinct(StringComparer.Ordinal)];
}
