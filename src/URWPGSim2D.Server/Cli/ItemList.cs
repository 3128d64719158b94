using URWPGSim2D.Engine.Items.Catalog;
using URWPGSim2D.Engine.Items;

namespace URWPGSim2D.Server.Cli;

/// <summary><c>run --list-items</c>: one line per competition item (slug, Chinese name, teams × fish, the rules in short).</summary>
internal static class ItemList
{
    /// <summary>The listing, ending in a newline.</summary>
    public static string Format()
    {
        // The slug column is as wide as the longest slug.
        int width = "default".Length;
        foreach (var item in ItemRegistry.All)
        {
            width = System.Math.Max(width, item.Slug.Length);
        }

        var s = new StringBuilder();
        foreach (var item in ItemRegistry.All)
        {
            s.Append(CultureInfo.InvariantCulture, $"{item.Slug.PadRight(width)} {item.ChineseName,-6} {item.TeamCount} x {item.FishPerTeam,-2} {item.Summary}\n");
        }

        s.Append(CultureInfo.InvariantCulture, $"{"default".PadRight(width)} {"-",-6} 2 x 2  the old default scene: 9 balls, 4 obstacles, goal blocks; a ball wholly in a goal mouth is a goal and goes back to its start\n");
        return s.ToString();
    }

    /// <summary>
    /// The error of an unknown <c>--item</c>: every name with the original's Chinese name beside it,
    /// what was given and, when one is near, the item it was probably meant to be. One line.
    /// </summary>
    /// <param name="command">The command, e.g. <c>run</c>.</param>
    /// <param name="value">The name given.</param>
    /// <param name="withDefault">Whether <c>default</c> (the old default scene) is a name too.</param>
    public static CliUsageException Unknown(string command, string value, bool withDefault)
    {
        var names = new List<string>();
        if (withDefault)
        {
            names.Add("default");
        }

        names.AddRange(ItemRegistry.All.Select(i => $"{i.Slug} ({i.ChineseName})"));
        var known = ItemRegistry.All.SelectMany(i => new[] { (Name: i.Slug, i.Slug), (Name: i.ChineseName, i.Slug) }).ToList();
        string? near = Suggestion.Nearest(value, known.Select(k => k.Name));
        string hint = near is null ? string.Empty : $"; did you mean {known.First(k => k.Name == near).Slug}?";
        return new CliUsageException($"{command}: --item must be one of {string.Join(", ", names)} (the name or the original's Chinese name, in any case), got {MessageText.Quote(value)}{hint}", null);
    }
}
