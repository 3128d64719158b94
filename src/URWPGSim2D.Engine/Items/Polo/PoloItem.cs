using System.Globalization;
using URWPGSim2D.Collision.Pool;
using URWPGSim2D.Engine.Trace;

namespace URWPGSim2D.Engine.Items.Polo;

/// <summary>
/// 水球 water polo 1v1, 3v3 or 5v5: two teams, one ball at the centre, goal blocks; a goal is the
/// ball wholly inside a goal; halves swap ends; equal scores go to 3 minutes of extra time, then
/// penalties, then a 5-minute golden-goal clutch shot. Fouls send a fish off: in the own goal for
/// more than 5 s, a third fish in the own forbidden zone for more than 5 s (3v3, 5v5), or a 5v5
/// defender or forward leaving its half. A ball held in a corner by both teams for 10 s is a dead
/// ball, restarted at the nearest free-ball spot.
/// </summary>
internal sealed class PoloItem(int perTeam) : CompetitionItem(
    slug: string.Create(CultureInfo.InvariantCulture, $"polo-{perTeam}v{perTeam}"),
    chineseName: string.Create(CultureInfo.InvariantCulture, $"水球{perTeam}VS{perTeam}"),
    summary: perTeam switch
    {
        1 => "water polo: goal = ball wholly in the goal; halves swap ends; tie: extra time, penalties, clutch shot; 5 s in own goal sends off; dead ball",
        3 => "water polo 3v3: as 1v1, plus a third fish 5 s in the own forbidden zone is sent off",
        _ => "water polo 5v5 on 4500 x 3000: as 3v3, plus defenders stay in their half and forwards in the other",
    },
    teamCount: 2,
    fishPerTeam: perTeam)
{
    /// <summary>Fish per team: 1, 3 or 5.</summary>
    public int PerTeam { get; } = perTeam;

    /// <inheritdoc/>
    public override ScenarioDefinition CreateScenario(ulong seed)
    {
        float l = PoloLayout.FieldLength(PerTeam) / 2f;
        float mouth = Field.GoalWidth / 2f;
        float zone = PoloLayout.ForbiddenZoneWidth / 2f;
        float inner = l - Field.GoalDepth - PoloLayout.ForbiddenZoneLength;
        var zones = new List<TraceZone>
        {
            TraceZone.Box("goal", 0, new Vector2(-l, -mouth), new Vector2(-l + Field.GoalDepth, mouth), team: 0),
            TraceZone.Box("goal", 1, new Vector2(l - Field.GoalDepth, -mouth), new Vector2(l, mouth), team: 1),
            TraceZone.Box("forbidden", 0, new Vector2(-l, -zone), new Vector2(-inner, zone), team: 0),
            TraceZone.Box("forbidden", 1, new Vector2(inner, -zone), new Vector2(l, zone), team: 1),
            TraceZone.Circle("centre", 0, Vector2.Zero, PoloLayout.CentreCircleRadius),
        };
        return FromLayout(PoloLayout.Scenario(PerTeam), seed, ballValues: [1], zones: zones);
    }

    /// <inheritdoc/>
    public override ItemReferee CreateReferee(ScenarioDefinition scenario, int cycles, ulong seed) => new PoloReferee(this, scenario, cycles);

    /// <inheritdoc/>
    public override IStrategy CreateDemoStrategy(int team, ItemReferee referee) => new PoloDemo(team, (PoloReferee)referee);
}
