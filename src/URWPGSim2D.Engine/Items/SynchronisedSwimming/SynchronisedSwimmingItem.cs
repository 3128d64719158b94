namespace URWPGSim2D.Engine.Items.SynchronisedSwimming;

/// <summary>
/// 花样游泳 synchronised swimming: one team of ten fish from random start poses swims a routine for
/// people to judge; the server drives fish 0 with random codes. No balls, no score.
/// </summary>
internal sealed class SynchronisedSwimmingItem() : CompetitionItem(
    slug: "synchronised-swimming",
    chineseName: "花样游泳",
    summary: "10 fish from random poses (seeded); the server drives fish 0 with random codes (seeded); judged by people: no score",
    teamCount: 1,
    fishPerTeam: SynchronisedSwimmingLayout.FishCount)
{
    /// <inheritdoc/>
    public override ScenarioDefinition CreateScenario(ulong seed) => FromLayout(SynchronisedSwimmingLayout.Scenario(seed), seed);

    /// <inheritdoc/>
    public override ItemReferee CreateReferee(ScenarioDefinition scenario, int cycles, ulong seed) => new SynchronisedSwimmingReferee(this, scenario, cycles, seed);

    /// <inheritdoc/>
    public override IStrategy CreateDemoStrategy(int team, ItemReferee referee) => new SynchronisedSwimmingDemo((SynchronisedSwimmingReferee)referee);
}
