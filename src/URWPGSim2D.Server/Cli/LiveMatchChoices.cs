using URWPGSim2D.Engine.Items.Catalog;
using URWPGSim2D.Engine.Items;
using URWPGSim2D.Engine.Scenario;

namespace URWPGSim2D.Server.Cli;

/// <summary>
/// The scenes the live view's control board offers: the default scene, every competition item (as
/// <c>--item</c> names them, laid out with <c>--seed</c>) and, when the command line gave
/// <c>--scenario FILE</c> or <c>--crowd N</c>, that scene (id <c>scene</c>); and the lengths
/// <c>--minutes</c> takes.
/// </summary>
internal sealed class LiveMatchChoices
{
    /// <summary>The lengths in minutes the board (and <c>--minutes</c>) offers.</summary>
    public static IReadOnlyList<int> Minutes { get; } = [10, 5, 3, 1];

    /// <summary>Lists the choices for the command line's options and scene.</summary>
    public LiveMatchChoices(RunOptions options, ScenarioDefinition scenario)
    {
        ulong seed = options.Seed ?? 1;
        var items = new List<Choice>();
        Choice? commandLine = null;
        if (options.Scenario is not null || options.Crowd is not null)
        {
            string name = options.Crowd is int n ? string.Create(CultureInfo.InvariantCulture, $"crowd {n}") : "scenario " + Path.GetFileName(options.Scenario!);
            commandLine = Of("scene", name, scenario.Item is not null, () => scenario, scenario);
            items.Add(commandLine);
        }

        items.Add(Of("default", "default scene", false, DefaultScenario.Load, options.Item == "default" ? scenario : null));
        foreach (var item in ItemRegistry.All)
        {
            bool chosen = commandLine is null && options.Item != "default" && ItemRegistry.Find(options.Item ?? RunCommand.MainItem) == item;
            items.Add(Of(item.Slug, item.Slug + " " + item.ChineseName, true, () => item.CreateScenario(seed), chosen ? scenario : null));
        }

        Items = items;
        CommandLine = commandLine ?? Find(options.Item ?? RunCommand.MainItem)!;
    }

    /// <summary>Every choice, in the board's order.</summary>
    public IReadOnlyList<Choice> Items { get; }

    /// <summary>The command line's scene.</summary>
    public Choice CommandLine { get; }

    /// <summary>The choice named <paramref name="name"/> (an id, or an item's slug or Chinese name in any case, as <c>--item</c> takes them), or null.</summary>
    public Choice? Find(string name)
    {
        string id = string.Equals(name, "default", StringComparison.OrdinalIgnoreCase) ? "default"
            : name == "scene" ? name
            : ItemRegistry.Find(name)?.Slug ?? name;
        foreach (var choice in Items)
        {
            if (choice.Id == id)
            {
                return choice;
            }
        }

        return null;
    }

    // A choice; its teams and regular length read from its scene (the command line's when it is the one chosen there).
    private static Choice Of(string id, string name, bool demo, Func<ScenarioDefinition> create, ScenarioDefinition? known)
    {
        var scene = known ?? create();
        int teams = 1;
        foreach (var f in scene.Fish)
        {
            teams = Math.Max(teams, f.Team + 1);
        }

        return new Choice(id, name, teams, scene.Cycles, demo, create);
    }

    /// <summary>A scene the board offers.</summary>
    /// <param name="Id">Its name in the board's protocol (<c>default</c>, an item's slug, or <c>scene</c>).</param>
    /// <param name="Name">What the board shows.</param>
    /// <param name="Teams">Teams with fish.</param>
    /// <param name="Cycles">Its regular length, cycles.</param>
    /// <param name="HasDemo">Whether it is a competition item (its teams may choose <c>demo</c>).</param>
    /// <param name="Create">Lays it out afresh.</param>
    public sealed record Choice(string Id, string Name, int Teams, int Cycles, bool HasDemo, Func<ScenarioDefinition> Create);
}
