using URWPGSim2D.Engine.Trace;

namespace URWPGSim2D.Engine.Items.Snooker;

/// <summary>
/// 斯诺克 water snooker: one fish, six red balls and four colours, six pockets. While reds are on the
/// table a red (1 point, stays down) and a colour (id − 4 points, re-spotted) must alternate,
/// starting with a red; then the colours go down in order 6, 7, 8, 9. A wrong pot scores nothing
/// (a red goes back beside a side wall, a colour to its spot). Ends when every ball is down or the
/// time is up.
/// </summary>
internal sealed class SnookerItem() : CompetitionItem(
    slug: "snooker",
    chineseName: "斯诺克",
    summary: "6 reds (1) and 4 colours (id - 4 = 2..5) into 6 pockets: red then colour while reds remain, then colours in order; ends when all are down",
    teamCount: 1,
    fishPerTeam: 1)
{
    /// <inheritdoc/>
    public override ScenarioDefinition CreateScenario(ulong seed)
    {
        var values = new List<double>();
        for (int i = 0; i < SnookerLayout.BallCount; i++)
        {
            values.Add(SnookerLayout.Value(i));
        }

        var zones = new List<TraceZone>();
        float half = SnookerLayout.FieldWidth / 2f;
        float[] x0 = [-SnookerLayout.FieldLength / 2f, -SnookerLayout.PocketWidth / 2f, (SnookerLayout.FieldLength / 2f) - SnookerLayout.PocketWidth];
        for (int row = 0; row < 2; row++)
        {
            for (int k = 0; k < 3; k++)
            {
                float zMin = row == 0 ? -half : half - SnookerLayout.PocketWidth;
                zones.Add(TraceZone.Box("hole", zones.Count, new Vector2(x0[k], zMin), new Vector2(x0[k] + SnookerLayout.PocketWidth, zMin + SnookerLayout.PocketWidth)));
            }
        }

        return FromLayout(SnookerLayout.Scenario(), seed, values, zones);
    }

    /// <inheritdoc/>
    public override ItemReferee CreateReferee(ScenarioDefinition scenario, int cycles, ulong seed) => new SnookerReferee(this, scenario, cycles);

    /// <inheritdoc/>
    public override IStrategy CreateDemoStrategy(int team, ItemReferee referee) => new SnookerDemo((SnookerReferee)referee);
}
