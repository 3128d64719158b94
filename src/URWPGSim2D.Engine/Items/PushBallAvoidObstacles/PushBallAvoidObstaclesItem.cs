namespace URWPGSim2D.Engine.Items.PushBallAvoidObstacles;

/// <summary>
/// 带球避障 push a ball past obstacles: one fish swims right through a passage in each of two
/// walls, then pushes the ball back through both until it is wholly past the black line at x = −500.
/// Touching an obstacle costs time (fish 5 s, ball 3 s) and puts the fish or ball back; the score is
/// the legs done (see <see cref="PushBallAvoidObstaclesReferee"/>).
/// </summary>
internal sealed class PushBallAvoidObstaclesItem() : CompetitionItem(
    slug: "push-ball-avoid-obstacles",
    chineseName: "带球避障",
    summary: "1 fish: 4 legs through two walls' passages (+1 each), the last two pushing the ball; ends when the ball is past x = -500; touching an obstacle: fish -5 s and back, ball -3 s and back",
    teamCount: 1,
    fishPerTeam: 1)
{
    /// <inheritdoc/>
    public override ScenarioDefinition CreateScenario(ulong seed) => FromLayout(PushBallAvoidObstaclesLayout.Scenario(), seed, ballValues: [1]);

    /// <inheritdoc/>
    public override ItemReferee CreateReferee(ScenarioDefinition scenario, int cycles, ulong seed) => new PushBallAvoidObstaclesReferee(this, scenario, cycles);

    /// <inheritdoc/>
    public override IStrategy CreateDemoStrategy(int team, ItemReferee referee) => new PushBallAvoidObstaclesDemo((PushBallAvoidObstaclesReferee)referee);
}
