namespace URWPGSim2D.Engine.Items.PushBallViaChannel;

/// <summary>
/// 协作过孔 two fish push a ball through channels: one team of two fish pushes the ball from the right
/// goal mouth through the channel of each of three walls and into the left goal; each of the four
/// stages scores 1 when both fish touched the ball during it (see <see cref="PushBallViaChannelReferee"/>).
/// </summary>
internal sealed class PushBallViaChannelItem() : CompetitionItem(
    slug: "push-ball-via-channel",
    chineseName: "协作过孔",
    summary: "2 fish push the ball past 3 walls through their channels and into the left goal; each of the 4 stages +1 if both fish touched the ball in it; ends when the ball is in the goal",
    teamCount: 1,
    fishPerTeam: 2)
{
    /// <inheritdoc/>
    public override ScenarioDefinition CreateScenario(ulong seed) => FromLayout(PushBallViaChannelLayout.Scenario(seed), seed, ballValues: [1]);

    /// <inheritdoc/>
    public override ItemReferee CreateReferee(ScenarioDefinition scenario, int cycles, ulong seed) => new PushBallViaChannelReferee(this, scenario, cycles);

    /// <inheritdoc/>
    public override IStrategy CreateDemoStrategy(int team, ItemReferee referee) => new PushBallViaChannelDemo((PushBallViaChannelReferee)referee);
}
