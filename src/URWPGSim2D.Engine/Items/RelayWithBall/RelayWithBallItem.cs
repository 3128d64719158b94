namespace URWPGSim2D.Engine.Items.RelayWithBall;

/// <summary>
/// 带球接力 relay with a ball: one team of two fish carries the ball between the two pockets of an
/// I-shaped obstacle four times, fish 0 through the top channel and fish 1 through the bottom one
/// (see <see cref="RelayWithBallReferee"/>).
/// </summary>
internal sealed class RelayWithBallItem() : CompetitionItem(
    slug: "relay-with-ball",
    chineseName: "带球接力",
    summary: "2 fish: 4 legs carrying the ball between the pockets either side of the centre post (+1 each); fish 0 keeps to the top channel, fish 1 to the bottom; legs 2-4 have their channel; a foul puts back the fish or ball",
    teamCount: 1,
    fishPerTeam: 2)
{
    /// <inheritdoc/>
    public override ScenarioDefinition CreateScenario(ulong seed) => FromLayout(RelayWithBallLayout.Scenario(), seed, ballValues: [1]);

    /// <inheritdoc/>
    public override ItemReferee CreateReferee(ScenarioDefinition scenario, int cycles, ulong seed) => new RelayWithBallReferee(this, scenario, cycles);

    /// <inheritdoc/>
    public override IStrategy CreateDemoStrategy(int team, ItemReferee referee) => new RelayWithBallDemo((RelayWithBallReferee)referee);
}
