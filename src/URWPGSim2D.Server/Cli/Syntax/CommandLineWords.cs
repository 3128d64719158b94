using System.CommandLine.Parsing;

namespace URWPGSim2D.Server.Cli.Syntax;

/// <summary>
/// The words of one command, in command-line order, from System.CommandLine's parse: which words
/// are the command's declared options, which word each option took as its value, and which are
/// positional. The commands check them and report problems in their own words; the parser's own
/// messages are never shown.
/// </summary>
internal static class CommandLineWords
{
    /// <summary>The words after the command's name.</summary>
    /// <param name="result">A parse whose innermost command is the command.</param>
    /// <returns>The words, in order.</returns>
    public static IReadOnlyList<CommandLineWord> Of(ParseResult result)
    {
        ArgumentNullException.ThrowIfNull(result);
        Command command = result.CommandResult.Command;
        var owners = new Dictionary<Token, Option>(ReferenceEqualityComparer.Instance);
        foreach (var child in result.CommandResult.Children)
        {
            if (child is OptionResult option)
            {
                foreach (Token token in option.Tokens)
                {
                    owners[token] = option.Option;
                }
            }
        }

        var words = new List<CommandLineWord>(result.Tokens.Count);
        bool named = false;
        foreach (Token token in result.Tokens)
        {
            switch (token.Type)
            {
                case TokenType.Directive:
                    break;
                case TokenType.Command when !named:
                    named = true;
                    break;
                case TokenType.Option:
                    words.Add(new CommandLineWord(token.Value, Find(command, token.Value), null));
                    break;
                default:
                    if (owners.TryGetValue(token, out Option? owner) && words.Count > 0 && words[^1] is { Value: null } last && last.Option == owner)
                    {
                        words[^1] = last with { Value = token.Value };
                    }
                    else
                    {
                        words.Add(new CommandLineWord(token.Value, null, null));
                    }

                    break;
            }
        }

        return words;
    }

    private static Option? Find(Command command, string name) =>
        command.Options.FirstOrDefault(o => o.Name == name || o.Aliases.Contains(name));
}
