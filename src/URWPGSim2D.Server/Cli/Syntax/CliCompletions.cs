using System.CommandLine.Completions;
using URWPGSim2D.Engine.Items.Catalog;
using URWPGSim2D.Engine.Items;
using URWPGSim2D.Tournament;

namespace URWPGSim2D.Server.Cli.Syntax;

/// <summary>
/// Completions of option values for the shells (<c>completion bash</c>): item names (slugs and the
/// original's Chinese names), strategy specs (built-in names, <c>remote:</c>, files), and paths.
/// </summary>
internal static class CliCompletions
{
    /// <summary>The built-in strategy names a spec may be.</summary>
    public static IReadOnlyList<string> BuiltInStrategies { get; } = [Entrant.Demo, .. StrategyResolver.BuiltInNames];

    /// <summary><c>--item</c> of <c>run</c>: every item's slug and Chinese name, and <c>default</c>.</summary>
    public static IEnumerable<CompletionItem> RunItems(CompletionContext context) => Items(context, withDefault: true);

    /// <summary><c>--item</c> of <c>tournament</c>: every item's slug and Chinese name.</summary>
    public static IEnumerable<CompletionItem> TournamentItems(CompletionContext context) => Items(context, withDefault: false);

    /// <summary><c>--strategy TEAM=SPEC</c>: <c>0=</c> … <c>3=</c>, then built-in names, <c>remote:</c> and paths after them.</summary>
    public static IEnumerable<CompletionItem> TeamStrategies(CompletionContext context)
    {
        ArgumentNullException.ThrowIfNull(context);
        string word = context.WordToComplete;
        if (word.Length < 2 || word[1] != '=' || word[0] is < '0' or > '3')
        {
            return Labels(["0=", "1=", "2=", "3="], word);
        }

        return Specs(word[..2], word[2..], remote: true);
    }

    /// <summary><c>--entrant NAME=SPEC</c>: built-in names, then paths, after the entrant's name.</summary>
    public static IEnumerable<CompletionItem> Entrants(CompletionContext context)
    {
        ArgumentNullException.ThrowIfNull(context);
        string word = context.WordToComplete;
        int eq = word.IndexOf('=', StringComparison.Ordinal);
        return eq < 0 ? [] : Specs(word[..(eq + 1)], word[(eq + 1)..], remote: false);
    }

    /// <summary>A strategy spec alone (<c>host SPEC</c>, <c>connect HOST:PORT SPEC</c>): built-in names and paths.</summary>
    public static IEnumerable<CompletionItem> Strategies(CompletionContext context)
    {
        ArgumentNullException.ThrowIfNull(context);
        return Specs(string.Empty, context.WordToComplete, remote: false);
    }

    /// <summary>Files and folders whose path begins with the word (folders end in <c>/</c>).</summary>
    public static IEnumerable<CompletionItem> Paths(CompletionContext context)
    {
        ArgumentNullException.ThrowIfNull(context);
        return PathsStartingWith(string.Empty, context.WordToComplete);
    }

    /// <summary>Folders whose path begins with the word.</summary>
    public static IEnumerable<CompletionItem> Folders(CompletionContext context)
    {
        ArgumentNullException.ThrowIfNull(context);
        return PathsStartingWith(string.Empty, context.WordToComplete).Where(c => c.Label.EndsWith('/'));
    }

    /// <summary>Fixed values (<c>on</c>, <c>off</c>, …) that begin with the word.</summary>
    /// <param name="values">The values.</param>
    public static Func<CompletionContext, IEnumerable<CompletionItem>> Fixed(params string[] values) =>
        context => Labels(values, context.WordToComplete);

    private static IEnumerable<CompletionItem> Items(CompletionContext context, bool withDefault)
    {
        ArgumentNullException.ThrowIfNull(context);
        IEnumerable<string> names = ItemRegistry.All.SelectMany(i => new[] { i.Slug, i.ChineseName });
        return Labels(withDefault ? names.Append("default") : names, context.WordToComplete);
    }

    private static IEnumerable<CompletionItem> Specs(string prefix, string rest, bool remote)
    {
        IEnumerable<string> names = remote ? BuiltInStrategies.Append(RunOptions.RemotePrefix) : BuiltInStrategies;
        return Labels(names.Select(n => prefix + n), prefix + rest).Concat(PathsStartingWith(prefix, rest));
    }

    private static IEnumerable<CompletionItem> Labels(IEnumerable<string> values, string word) =>
        values.Where(v => v.StartsWith(word, StringComparison.OrdinalIgnoreCase)).Select(v => new CompletionItem(v));

    // The entries of the word's folder whose names begin with its last part; folders with a '/'.
    private static IEnumerable<CompletionItem> PathsStartingWith(string prefix, string word)
    {
        int slash = word.LastIndexOf('/');
        string folder = slash < 0 ? string.Empty : word[..(slash + 1)];
        string start = word[(slash + 1)..];
        string look = folder.Length == 0 ? "." : folder;
        IEnumerable<string> entries;
        try
        {
            if (!Directory.Exists(look))
            {
                return [];
            }

            entries = [.. Directory.EnumerateFileSystemEntries(look)
                .Select(e => Directory.Exists(e) ? Path.GetFileName(e) + "/" : Path.GetFileName(e))
                .Where(n => n.StartsWith(start, StringComparison.Ordinal) && (start.StartsWith('.') || !n.StartsWith('.')))
                .Order(StringComparer.Ordinal)];
        }
        catch (Exception e) when (e is IOException or UnauthorizedAccessException or ArgumentException)
        {
            return [];
        }

        return entries.Select(n => new CompletionItem(prefix + folder + n));
    }
}
