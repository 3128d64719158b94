namespace URWPGSim2D.Server.Cli.Syntax;

/// <summary>
/// A command's usage line, written once as the terms that declare its options: each option is
/// created inside the term that places it (<see cref="Optional"/>, <see cref="OneOf"/>, …), so the
/// usage text (<see cref="Text"/>) and the declared options the parser and shell completion use
/// (<see cref="Symbols"/>, given to <see cref="CliSyntax.Command(string, string, UsageLine, System.CommandLine.Option{bool})"/>) come from the same declarations.
/// An option is shown as its name and value name (<c>--seed S</c>); one that may be given again is
/// followed by <c>...</c>, one that takes every following word has <c>...</c> after its value name;
/// a positional argument is shown as its name.
/// </summary>
internal sealed class UsageLine
{
    private readonly Term[] _terms;

    /// <summary>A usage line of the given terms, in order.</summary>
    /// <param name="terms">The command's words, options and groups of options.</param>
    public UsageLine(params Term[] terms)
    {
        _terms = terms;
    }

    /// <summary>The usage text after the command's name, e.g. <c>[--out FILE [--force]] FILE...</c>.</summary>
    public string Text => string.Join(' ', _terms.Select(t => t.Render()));

    /// <summary>Every option the line declares, in the order it names them.</summary>
    public IReadOnlyList<Option> Options => [.. _terms.SelectMany(t => t.Symbols).OfType<Option>()];

    /// <summary>Every option and positional argument the line declares, in order.</summary>
    public IReadOnlyList<Symbol> Symbols => [.. _terms.SelectMany(t => t.Symbols)];

    /// <summary>An option or a group that is not required: <c>[--seed S]</c>, <c>[--live [--port N]]</c>.</summary>
    /// <param name="terms">The option (and what belongs to it).</param>
    public static Term Optional(params Term[] terms) => new Group("[", terms, "]");

    /// <summary>A required group: <c>(--out DIR | --check)</c>.</summary>
    /// <param name="terms">The group's terms.</param>
    public static Term Required(params Term[] terms) => new Group("(", terms, ")");

    /// <summary>Alternatives, at most one of which is given: <c>--item NAME | --scenario FILE</c>.</summary>
    /// <param name="terms">The alternatives.</param>
    public static Term OneOf(params Term[] terms) => new Choice(terms);

    /// <summary>A term that may be given again: <c>(--entrant NAME=SPEC | --entrants-dir DIR)...</c>.</summary>
    /// <param name="term">The term.</param>
    public static Term Repeated(Term term) => new Repetition(term);

    /// <summary>
    /// The options and their one-line descriptions as an indented table, one line each:
    /// <c>  --token T         the token …</c>, the names padded to <paramref name="width"/>.
    /// </summary>
    /// <param name="width">The width of the name column.</param>
    public string OptionTable(int width)
    {
        var text = new StringBuilder();
        foreach (Option option in Options)
        {
            text.Append("  ").Append(Named(option).PadRight(width)).Append(option.Description).Append('\n');
        }

        return text.ToString();
    }

    // --name, --name VALUE or --name VALUE...
    private static string Named(Option option) =>
        !CliSyntax.TakesValue(option) ? option.Name
        : option.Arity.MaximumNumberOfValues > 1 ? $"{option.Name} {option.HelpName}..."
        : $"{option.Name} {option.HelpName}";

    // Whether the option may be given again, each time with one value.
    private static bool IsRepeatable(Option option) =>
        option.ValueType == typeof(string[]) && option.Arity.MaximumNumberOfValues == 1;

    /// <summary>One part of a usage line: an option, a fixed word or a group.</summary>
    internal abstract class Term
    {
        /// <summary>The options and arguments it declares.</summary>
        public abstract IEnumerable<Symbol> Symbols { get; }

        /// <summary>An option as a term: its name and value name.</summary>
        /// <param name="option">The option's declaration.</param>
        public static implicit operator Term(Option option) => new Single(option);

        /// <summary>A positional argument as a term: its name (<c>FILE</c>).</summary>
        /// <param name="argument">The argument's declaration.</param>
        public static implicit operator Term(Argument argument) => new Positional(argument);

        /// <summary>The term's text.</summary>
        public abstract string Render();
    }

    private sealed class Single(Option option) : Term
    {
        public Option Option { get; } = option;

        public override IEnumerable<Symbol> Symbols => [Option];

        public override string Render() => Named(Option);
    }

    private sealed class Positional(Argument argument) : Term
    {
        public override IEnumerable<Symbol> Symbols => [argument];

        public override string Render() => argument.Name;
    }

    private sealed class Group(string open, Term[] terms, string close) : Term
    {
        public override IEnumerable<Symbol> Symbols => terms.SelectMany(t => t.Symbols);

        // An optional option that may be given again is followed by "...": [--strategy TEAM=SPEC]...
        public override string Render() =>
            open + string.Join(' ', terms.Select(t => t.Render())) + close
            + (terms is [Single { Option: var o }] && IsRepeatable(o) ? "..." : string.Empty);
    }

    private sealed class Choice(Term[] terms) : Term
    {
        public override IEnumerable<Symbol> Symbols => terms.SelectMany(t => t.Symbols);

        public override string Render() => string.Join(" | ", terms.Select(t => t.Render()));
    }

    private sealed class Repetition(Term term) : Term
    {
        public override IEnumerable<Symbol> Symbols => term.Symbols;

        public override string Render() => term.Render() + "...";
    }
}
