using URWPGSim2D.Engine.Trace;

namespace URWPGSim2D.Engine.Items.CrossCountry;

/// <summary>
/// 障碍越野 obstacle cross-country: one fish, two balls, three round posts and four blocks. The fish
/// must touch ball 0, bring its centre within 22 mm of target 0 at (1900, −1200), then touch ball 1
/// and bring it within 22 mm of target 1 at (1900, 1200); the match ends when both are home or the
/// time is up. The times of the four steps are the result (the original shows them; the score is
/// the number of balls home).
/// </summary>
internal sealed class CrossCountryItem() : CompetitionItem(
    slug: "cross-country",
    chineseName: "障碍越野",
    summary: "1 fish: touch ball 0, bring it within 22 mm of its target, then the same with ball 1; ends when both are home; times reported",
    teamCount: 1,
    fishPerTeam: 1)
{
    /// <inheritdoc/>
    public override ScenarioDefinition CreateScenario(ulong seed) => FromLayout(
        CrossCountryLayout.Scenario(),
        seed,
        ballValues: [1, 1],
        zones:
        [
            TraceZone.Circle("target", 0, CrossCountryLayout.Targets[0], CrossCountryLayout.TargetTolerance),
            TraceZone.Circle("target", 1, CrossCountryLayout.Targets[1], CrossCountryLayout.TargetTolerance),
        ]);

    /// <inheritdoc/>
    public override ItemReferee CreateReferee(ScenarioDefinition scenario, int cycles, ulong seed) => new CrossCountryReferee(this, scenario, cycles);

    /// <inheritdoc/>
    public override IStrategy CreateDemoStrategy(int team, ItemReferee referee) => new CrossCountryDemo((CrossCountryReferee)referee);
}
