using URWPGSim2D.Engine.Trace;
using URWPGSim2D.Strategies;

namespace URWPGSim2D.Engine.Items;

/// <summary>
/// One competition item of the original (抢球博弈 ball-grab, 生存挑战 survival, …): its names, how
/// many teams and fish play it, its layout at cycle 0, a referee for its rules and a demo strategy.
/// To add an item, write a folder under <c>Items/</c> with a subclass of this and a subclass of
/// <see cref="ItemReferee"/> (and its demo strategy), and list it in <see cref="Catalog.ItemRegistry"/>;
/// see docs/items.md, "Adding an item".
/// </summary>
/// <param name="slug">English slug for <c>run --item</c>, e.g. "ball-grab".</param>
/// <param name="chineseName">The original's name, e.g. "抢球博弈".</param>
/// <param name="summary">The rules in one line for <c>run --list-items</c>.</param>
/// <param name="teamCount">Number of teams.</param>
/// <param name="fishPerTeam">Fish per team.</param>
public abstract class CompetitionItem(string slug, string chineseName, string summary, int teamCount, int fishPerTeam) : IScenarioItem
{
    /// <summary>Cycles of the default duration, ten minutes.</summary>
    public const int DefaultCycles = 6000;

    /// <summary>English slug for <c>run --item</c>, e.g. "ball-grab".</summary>
    public string Slug { get; } = Named(slug, nameof(slug));

    /// <summary>The original's name, e.g. "抢球博弈" (also accepted by <c>--item</c>).</summary>
    public string ChineseName { get; } = Named(chineseName, nameof(chineseName));

    /// <summary>The rules in one line for <c>run --list-items</c>.</summary>
    public string Summary { get; } = Named(summary, nameof(summary));

    /// <summary>Number of teams (1, 2 or 4).</summary>
    public int TeamCount { get; } = teamCount >= 1 ? teamCount : throw new ArgumentOutOfRangeException(nameof(teamCount), teamCount, "an item has at least one team");

    /// <summary>Fish per team.</summary>
    public int FishPerTeam { get; } = fishPerTeam >= 1 ? fishPerTeam : throw new ArgumentOutOfRangeException(nameof(fishPerTeam), fishPerTeam, "a team has at least one fish");

    /// <summary>
    /// The layout at cycle 0 as a scenario: field, obstacles, balls, fish start poses (every fish on
    /// the "demo" strategy), ball values and zones, <see cref="DefaultCycles"/> cycles, noise on.
    /// Items with random start poses draw them from <paramref name="seed"/>.
    /// </summary>
    public abstract ScenarioDefinition CreateScenario(ulong seed);

    /// <summary>A referee for one match of <paramref name="cycles"/> cycles on <paramref name="scenario"/> (this item's layout, positions possibly overridden).</summary>
    public abstract ItemReferee CreateReferee(ScenarioDefinition scenario, int cycles, ulong seed);

    /// <summary>The built-in demo strategy of a team; it may read the referee's state.</summary>
    public abstract IStrategy CreateDemoStrategy(int team, ItemReferee referee);

    /// <summary>
    /// This item's scenario from its <paramref name="layout"/>: the layout played for
    /// <see cref="DefaultCycles"/> with <paramref name="seed"/>, refereed as this item, with the balls'
    /// <paramref name="ballValues"/> and the <paramref name="zones"/> drawn (the layout's own where null).
    /// </summary>
    private protected ScenarioDefinition FromLayout(ScenarioDefinition layout, ulong seed, IReadOnlyList<double>? ballValues = null, IReadOnlyList<TraceZone>? zones = null) =>
        layout with
        {
            Cycles = DefaultCycles,
            Seed = seed,
            Item = this,
            BallValues = ballValues ?? layout.BallValues,
            Zones = zones ?? layout.Zones,
        };

    private static string Named(string value, string name) =>
        string.IsNullOrWhiteSpace(value) ? throw new ArgumentException($"{name} is empty", name) : value;
}
