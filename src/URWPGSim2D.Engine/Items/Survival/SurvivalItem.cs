using URWPGSim2D.Engine.Trace;

namespace URWPGSim2D.Engine.Items.Survival;

/// <summary>
/// 生存挑战 survival: two teams of four fish, no balls, three squares across the middle. In each
/// half one team hunts with its fish 0 (its fish 1–3 parked off the field) and the other team's
/// fish 1–3 are the prey, at speed gear 8 at most: the hunter touching a prey fish catches it (+1;
/// the prey is parked off the field). A half ends after its time or at three catches; the roles swap
/// at half time. Equal scores: the earlier last catch, counted from the start of each half, wins.
/// </summary>
internal sealed class SurvivalItem() : CompetitionItem(
    slug: "survival",
    chineseName: "生存挑战",
    summary: "fish 0 hunts the other team's fish 1-3 (speed gear <= 8): +1 per catch by touch, the prey parked; a half ends at 3 catches; halves swap hunter and prey; tie: earlier last catch",
    teamCount: 2,
    fishPerTeam: SurvivalLayout.FishPerTeam)
{
    /// <inheritdoc/>
    public override ScenarioDefinition CreateScenario(ulong seed)
    {
        var zones = new TraceZone[6];
        for (int j = 1; j < SurvivalLayout.FishPerTeam; j++)
        {
            zones[j - 1] = TraceZone.Circle("parking", j - 1, SurvivalLayout.Hunters[j], 20f);
            zones[j + 2] = TraceZone.Circle("parking", j + 2, SurvivalLayout.CaughtPlace(j), 20f);
        }

        return FromLayout(SurvivalLayout.Scenario(), seed, zones: zones);
    }

    /// <inheritdoc/>
    public override ItemReferee CreateReferee(ScenarioDefinition scenario, int cycles, ulong seed) => new SurvivalReferee(this, scenario, cycles);

    /// <inheritdoc/>
    public override IStrategy CreateDemoStrategy(int team, ItemReferee referee) => new SurvivalDemo(team, (SurvivalReferee)referee);
}
