using static URWPGSim2D.Engine.Items.BallGrab.BallGrabLayout;

namespace URWPGSim2D.Engine.Items.BallGrab;

/// <summary>
/// 抢球博弈 ball-grab: two teams of two fish and nine balls of three sizes; a team scores a ball's
/// value the first time that ball lies wholly inside the team's own goal box (the box at the end
/// it starts from). Two halves; at half time the teams change ends and the balls are mirrored
/// through the centre. Equal scores: the earlier first score wins.
/// </summary>
internal sealed class BallGrabItem() : CompetitionItem(
    slug: "ball-grab",
    chineseName: "抢球博弈",
    summary: "9 balls worth 3/2/1; a ball's value once per team on its first entry into the team's goal box; halves swap ends; tie: earlier first score",
    teamCount: 2,
    fishPerTeam: 2)
{
    /// <inheritdoc/>
    public override ScenarioDefinition CreateScenario(ulong seed)
    {
        var balls = new List<BallDefinition>();
        var values = new List<double>();
        for (int i = 0; i < BallStarts.Length; i++)
        {
            balls.Add(new BallDefinition(BallStarts[i], Vector2.Zero, Radii[i]));
            values.Add(Values[i]);
        }

        return new ScenarioDefinition
        {
            FieldLength = 3000f,
            FieldWidth = 2000f,
            GoalBlocks = false,
            Cycles = DefaultCycles,
            Seed = seed,
            Fish = StartFish(),
            Balls = balls,
            Obstacles = BoxObstacles(),
            Item = this,
            BallValues = values,
            Zones = BoxZones(),
        };
    }

    /// <inheritdoc/>
    public override ItemReferee CreateReferee(ScenarioDefinition scenario, int cycles, ulong seed) => new BallGrabReferee(this, scenario, cycles);

    /// <inheritdoc/>
    public override IStrategy CreateDemoStrategy(int team, ItemReferee referee) => new BallGrabDemo((BallGrabReferee)referee);
}
