using URWPGSim2D.Engine.Trace;

namespace URWPGSim2D.Engine.Items.Transport;

/// <summary>
/// 水中搬运 underwater transport: one team of two fish brings six balls, one by one, from their
/// triangle on the right into six holes on the left; ball i scores 1 when its centre comes within
/// 22 mm of hole i. The match ends when all six are in or the time is up; the time of the last
/// ball in is reported.
/// </summary>
internal sealed class TransportItem() : CompetitionItem(
    slug: "transport",
    chineseName: "水中搬运",
    summary: "2 fish, 6 balls: +1 when ball i's centre comes within 22 mm of hole i (once per ball); ends when all 6 are in; time of the last reported",
    teamCount: 1,
    fishPerTeam: 2)
{
    /// <inheritdoc/>
    public override ScenarioDefinition CreateScenario(ulong seed)
    {
        var zones = new TraceZone[TransportLayout.Count];
        for (int i = 0; i < zones.Length; i++)
        {
            zones[i] = TraceZone.Circle("hole", i, TransportLayout.Holes[i], TransportLayout.HoleRadius);
        }

        return FromLayout(TransportLayout.Scenario(), seed, ballValues: [1, 1, 1, 1, 1, 1], zones: zones);
    }

    /// <inheritdoc/>
    public override ItemReferee CreateReferee(ScenarioDefinition scenario, int cycles, ulong seed) => new TransportReferee(this, scenario, cycles);

    /// <inheritdoc/>
    public override IStrategy CreateDemoStrategy(int team, ItemReferee referee) => new TransportDemo((TransportReferee)referee);
}
