using URWPGSim2D.Engine.BuiltInStrategies;
using URWPGSim2D.Strategies;

namespace URWPGSim2D.Engine.Items.PlainScene;

/// <summary>
/// The plain scene — the default scene, crowds and scenario files without an item — as an item
/// like the others, so that every match is scored by one system, an item's referee
/// (<see cref="PlainSceneReferee"/>: a ball in a goal mouth scores). It is not a competition item:
/// <c>items</c> does not list it and <c>--item</c> does not take it; a match of a plain scene has no
/// <see cref="Matches.Match.Referee"/> of a competition item.
/// </summary>
internal sealed class PlainScene : CompetitionItem
{
    private PlainScene()
        : base(
            slug: "default",
            chineseName: "match",
            summary: "the plain scene: a ball wholly inside a goal mouth scores for the attacking team",
            teamCount: 2,
            fishPerTeam: 2)
    {
    }

    /// <summary>The one instance.</summary>
    public static PlainScene Instance { get; } = new();

    /// <inheritdoc/>
    public override ScenarioDefinition CreateScenario(ulong seed) => DefaultScenario.Load() with { Seed = seed };

    /// <inheritdoc/>
    public override ItemReferee CreateReferee(ScenarioDefinition scenario, int cycles, ulong seed) => new PlainSceneReferee(cycles);

    /// <inheritdoc/>
    public override IStrategy CreateDemoStrategy(int team, ItemReferee referee) => new ChaseBallStrategy();
}
