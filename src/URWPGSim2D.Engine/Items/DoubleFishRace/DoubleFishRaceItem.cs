namespace URWPGSim2D.Engine.Items.DoubleFishRace;

/// <summary>
/// 双鱼竞速 two fish race through holes: one fish per team, starting half a lap apart, swims round the
/// centre wall through its holes; the match ends when one catches up with the other, and the larger
/// angle swum wins (see <see cref="DoubleFishRaceReferee"/>).
/// </summary>
internal sealed class DoubleFishRaceItem() : CompetitionItem(
    slug: "double-fish-race-via-holes",
    chineseName: "双鱼竞速",
    summary: "1 fish each, half a lap apart, round the centre wall through its holes; ends when one catches up (angles within 2 degrees); larger angle swum wins; going back or cutting across: put back",
    teamCount: 2,
    fishPerTeam: 1)
{
    /// <inheritdoc/>
    public override ScenarioDefinition CreateScenario(ulong seed) => FromLayout(DoubleFishRaceLayout.Scenario(), seed);

    /// <inheritdoc/>
    public override ItemReferee CreateReferee(ScenarioDefinition scenario, int cycles, ulong seed) => new DoubleFishRaceReferee(this, scenario, cycles);

    /// <inheritdoc/>
    public override IStrategy CreateDemoStrategy(int team, ItemReferee referee) => new DoubleFishRaceDemo();
}
