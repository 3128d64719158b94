using URWPGSim2D.Engine.Items.BallGrab;

namespace URWPGSim2D.Engine.Items.NewBallGrab;

/// <summary>
/// 抢球大作战 the older ball-grab (the original's <c>NewMatch2V2BallRace</c>, Match/NewMatch2V2.cs):
/// the goal boxes, fish and field of 抢球博弈 (<see cref="BallGrabLayout"/>), nine standard balls in a
/// 3 × 3 grid 120 apart at the centre; a team's score is what lies in its box now — 1 a ball, 3 the
/// centre ball — two halves, and a clutch shot on a tie (see <see cref="NewBallGrabReferee"/>).
/// </summary>
internal sealed class NewBallGrabItem() : CompetitionItem(
    slug: "new-ball-grab",
    chineseName: "抢球大作战",
    summary: "9 balls in a grid, the centre one worth 3, the rest 1; a team's score is what lies in its goal box now; halves swap ends; tie: clutch shot of 5 min, first to lead wins",
    teamCount: 2,
    fishPerTeam: 2)
{
    /// <summary>Ball radius, mm (every ball is the standard one).</summary>
    public const float BallRadius = 58f;

    /// <summary>The ball worth 3 (the centre of the grid, drawn dark orange and black in the original).</summary>
    public const int CentreBall = 4;

    /// <summary>Ball i's start: row i / 3 at x = 40 × (i − i % 3 − 3), column i % 3 at z = 120 × (i % 3 − 1), as the original's loop.</summary>
    public static Vector2 BallStart(int i) => new(40f * ((i - (i % 3)) - 3), 120f * ((i % 3) - 1));

    /// <inheritdoc/>
    public override ScenarioDefinition CreateScenario(ulong seed)
    {
        var balls = new List<BallDefinition>();
        var values = new List<double>();
        for (int i = 0; i < 9; i++)
        {
            balls.Add(new BallDefinition(BallStart(i), Vector2.Zero, BallRadius));
            values.Add(i == CentreBall ? 3 : 1);
        }

        return new ScenarioDefinition
        {
            FieldLength = 3000f,
            FieldWidth = 2000f,
            GoalBlocks = false,
            Cycles = DefaultCycles,
            Seed = seed,
            Fish = BallGrabLayout.StartFish(),
            Balls = balls,
            Obstacles = BallGrabLayout.BoxObstacles(),
            Item = this,
            BallValues = values,
            Zones = BallGrabLayout.BoxZones(),
        };
    }

    /// <inheritdoc/>
    public override ItemReferee CreateReferee(ScenarioDefinition scenario, int cycles, ulong seed) => new NewBallGrabReferee(this, scenario, cycles);

    /// <inheritdoc/>
    public override IStrategy CreateDemoStrategy(int team, ItemReferee referee) => new BallGrabDemo((NewBallGrabReferee)referee, "new-ball-grab demo");
}
