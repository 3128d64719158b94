using System.Collections.Generic;
using System.Numerics;
using URWPGSim2D.Collision.Fish;
using URWPGSim2D.Server.Scenario;
using URWPGSim2D.Server.Simulation;
using URWPGSim2D.Server.Trace;
using URWPGSim2D.Strategies;
using static URWPGSim2D.Server.Items.BallGrab.BallGrabLayout;

namespace URWPGSim2D.Server.Items.BallGrab;

/// <summary>
/// 抢球博弈 ball-grab: two teams of two fish and nine balls of three sizes; a team scores a ball's
/// value the first time that ball lies wholly inside the team's own goal box (the box at the end
/// it starts from). Two halves; at half time the teams change ends and the balls are mirrored
/// through the centre. Equal scores: the earlier first score wins.
/// </summary>
internal sealed class BallGrabItem : CompetitionItem
{
    /// <inheritdoc/>
    public override string Slug => "ball-grab";

    /// <inheritdoc/>
    public override string ChineseName => "抢球博弈";

    /// <inheritdoc/>
    public override string Summary => "9 balls worth 3/2/1; a ball's value once per team on its first entry into the team's goal box; halves swap ends; tie: earlier first score";

    /// <inheritdoc/>
    public override int TeamCount => 2;

    /// <inheritdoc/>
    public override int FishPerTeam => 2;

    /// <inheritdoc/>
    public override ScenarioDefinition CreateScenario(ulong seed)
    {
        FishSize size = FishSize.Default;
        float x = HalfLength - (size.Length * 6f);
        float z = size.Width * 3f;
        var fish = new List<FishDefinition>
        {
            new(0, new Vector2(-x, z), 0f, "demo", Decision.Stop),
            new(0, new Vector2(-x, -z), 0f, "demo", Decision.Stop),
            new(1, new Vector2(x, z), System.MathF.PI, "demo", Decision.Stop),
            new(1, new Vector2(x, -z), System.MathF.PI, "demo", Decision.Stop),
        };
        var balls = new List<BallDefinition>();
        var values = new List<double>();
        for (int i = 0; i < BallStarts.Length; i++)
        {
            balls.Add(new BallDefinition(BallStarts[i], Vector2.Zero, Radii[i]));
            values.Add(Values[i]);
        }

        var obstacles = new List<ObstacleDefinition>
        {
            Rectangle(-BarX, BarZ, BarLength, BarWidth),
            Rectangle(-BarX, -BarZ, BarLength, BarWidth),
            Rectangle(BarX, BarZ, BarLength, BarWidth),
            Rectangle(BarX, -BarZ, BarLength, BarWidth),
            Rectangle(-BackX, 0, BackLength, BackWidth),
            Rectangle(BackX, 0, BackLength, BackWidth),
        };
        var zones = new List<TraceZone>
        {
            TraceZone.Box("goal-box", 0, new Vector2(-BoxOuterX, -BoxHalfWidth), new Vector2(-BoxInnerX, BoxHalfWidth), team: 0),
            TraceZone.Box("goal-box", 1, new Vector2(BoxInnerX, -BoxHalfWidth), new Vector2(BoxOuterX, BoxHalfWidth), team: 1),
        };
        return new ScenarioDefinition
        {
            FieldLength = 3000f,
            FieldWidth = 2000f,
            GoalBlocks = false,
            Cycles = DefaultCycles,
            Seed = seed,
            Fish = fish,
            Balls = balls,
            Obstacles = obstacles,
            Item = this,
            BallValues = values,
            Zones = zones,
        };
    }

    /// <inheritdoc/>
    public override ItemReferee CreateReferee(ScenarioDefinition scenario, int cycles, ulong seed) => new BallGrabReferee(this, scenario, cycles);

    /// <inheritdoc/>
    public override IStrategy CreateDemoStrategy(int team, ItemReferee referee) => new BallGrabDemo((BallGrabReferee)referee);

    private static ObstacleDefinition Rectangle(float x, float z, float length, float width) =>
        new(ObstacleKind.Rectangle, new Vector2(x, z), length, width, 0f, 0f);
}
