using URWPGSim2D.Engine.Trace;

namespace URWPGSim2D.Engine.Items.Rescue;

/// <summary>
/// 急速救援 quick rescue: two teams of two fish. In each half one team rescues: its two fish push
/// the two balls from the left half through a slalom of five walls into the rescue zone at the right
/// end (+1 per ball whose centre enters the zone); the other team defends with one fish, its second
/// fish parked off the field. A half ends after its time or at two rescues; the roles swap at half
/// time. Equal scores: the earlier second rescue, then the earlier first rescue, then the earlier
/// first touch of a ball wins (times counted from the start of each team's half).
/// </summary>
internal sealed class RescueItem() : CompetitionItem(
    slug: "rescue",
    chineseName: "急速救援",
    summary: "2 balls; +1 per ball whose centre enters the rescue zone; a half ends at 2 rescues; halves swap rescuer and defender; tie: earlier rescues, then earlier first touch",
    teamCount: 2,
    fishPerTeam: 2)
{
    /// <inheritdoc/>
    public override ScenarioDefinition CreateScenario(ulong seed) => FromLayout(
        RescueLayout.Scenario(),
        seed,
        ballValues: [1, 1],
        zones:
        [
            TraceZone.Box("rescue", 0, RescueLayout.ZoneMin, RescueLayout.ZoneMax),
            TraceZone.Circle("parking", 0, RescueLayout.ParkedFish, 20f, team: 1),
        ]);

    /// <inheritdoc/>
    public override ItemReferee CreateReferee(ScenarioDefinition scenario, int cycles, ulong seed) => new RescueReferee(this, scenario, cycles);

    /// <inheritdoc/>
    public override IStrategy CreateDemoStrategy(int team, ItemReferee referee) => new RescueDemo(team, (RescueReferee)referee);
}
