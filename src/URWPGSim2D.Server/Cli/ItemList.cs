using System.Globalization;
using System.Text;
using URWPGSim2D.Server.Items;

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
}
