namespace URWPGSim2D.Engine.Items.FourTeams;

/// <summary>
/// 4支队伍测试 four teams (the original's <c>Match4Teams</c>, Match/Match4Teams.cs): a test of a
/// match with four teams of three fish, one from each side of the pool, and one ball at the centre;
/// the original gives it no rules and no score (see <see cref="FourTeamsReferee"/>).
/// </summary>
internal sealed class FourTeamsItem() : CompetitionItem(
    slug: "four-teams",
    chineseName: "4支队伍测试",
    summary: "4 teams of 3 fish, one from each side, and a ball at the centre: a test of four teams, no rules and no score; ends with the time",
    teamCount: 4,
    fishPerTeam: 3)
{
    /// <summary>The fish's body length in the original, mm.</summary>
    public const float BodyLength = 160f;

    /// <summary>The fish's body width in the original, mm.</summary>
    public const float BodyWidth = 45f;

    /// <summary>
    /// The start pose of fish <paramref name="j"/> (0–2) of team <paramref name="team"/> (0–3): teams 0 and 1
    /// 3 body lengths from the left and right walls at z 0, +135, −135 facing the centre; teams 2 and 3
    /// 3 body lengths from the top and bottom walls at x 0, +135, −135 facing the centre.
    /// </summary>
    public static (Vector2 Position, float Heading) Start(int team, int j)
    {
        float side = j == 0 ? 0f : j == 1 ? 3f * BodyWidth : -3f * BodyWidth;
        float x = 1500f - (3f * BodyLength), z = 1000f - (3f * BodyLength);
        return team switch
        {
            0 => (new Vector2(-x, side), 0f),
            1 => (new Vector2(x, side), System.MathF.PI),
            2 => (new Vector2(side, -z), System.MathF.PI / 2f),
            _ => (new Vector2(side, z), -System.MathF.PI / 2f),
        };
    }

    /// <inheritdoc/>
    public override ScenarioDefinition CreateScenario(ulong seed)
    {
        var fish = new List<FishDefinition>();
        for (int team = 0; team < TeamCount; team++)
        {
            for (int j = 0; j < FishPerTeam; j++)
            {
                var (position, heading) = Start(team, j);
                fish.Add(new FishDefinition(team, position, heading, "demo", Decision.Stop));
            }
        }

        return new ScenarioDefinition
        {
            FieldLength = 3000f,
            FieldWidth = 2000f,
            GoalBlocks = false,
            Cycles = DefaultCycles,
            Seed = seed,
            Fish = fish,
            Balls = [new BallDefinition(Vector2.Zero, Vector2.Zero, 58f)],
            Item = this,
        };
    }

    /// <inheritdoc/>
    public override ItemReferee CreateReferee(ScenarioDefinition scenario, int cycles, ulong seed) => new FourTeamsReferee(this, scenario, cycles);

    /// <inheritdoc/>
    public override IStrategy CreateDemoStrategy(int team, ItemReferee referee) => new FourTeamsDemo(team);
}
