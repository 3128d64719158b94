using URWPGSim2D.Engine.Matches;

namespace URWPGSim2D.Server.Tests.Hosting;

/// <summary>
/// The built-in chase-ball strategy, pinned by what it must do in a match (noise off): it turns
/// toward a ball beside it (whichever side), closes in on it, and drives a ball lying in front of
/// it toward the goal it attacks. The expectations are geometric (signs of angles, distances), not
/// numbers taken from the strategy, so a strategy turning away or pushing the wrong way fails.
/// </summary>
public sealed class ChaseBallStrategyTests
{
    [Theory]
    [InlineData(1, 0)]   // team 0 (attacks +X), ball toward +Z
    [InlineData(-1, 0)]  // ball toward −Z
    [InlineData(1, 1)]   // team 1 (attacks −X), heading π, ball toward +Z
    [InlineData(-1, 1)]
    public void ItTurnsTowardABallBesideItAndClosesIn(int side, int team)
    {
        float heading = team == 0 ? 0f : MathF.PI;
        var fishAt = new Vector2(0f, 0f);
        var ballAt = new Vector2(0f, side * 500f);
        var match = Match(team, fishAt, heading, ballAt);
        float startDistance = Vector2.Distance(match.World.Fish[0].Position, ballAt);

        match.Play(40);
        FishState fish = match.World.Fish[0];
        // Heading is measured from +X toward +Z: turning toward +Z raises it for team 0 and lowers it
        // (from π) for team 1, so the turn's sign is side·(team 0 ? +1 : −1). The fish turns at about
        // 0.3 rad/s: in 4 s well over half a radian.
        float turned = WrapAngle(fish.Heading - heading) * (team == 0 ? 1f : -1f);
        Assert.True(turned * side > 0.5f, $"side {side}, team {team}: after 40 cycles the fish turned {turned} rad (heading {fish.Heading}), not toward the ball");

        match.Play(60);
        float distance = Vector2.Distance(match.World.Fish[0].Position, match.BallAt(0));
        Assert.True(distance < startDistance - 250f, $"side {side}, team {team}: after 100 cycles the fish is {distance} mm from the ball (started {startDistance})");
    }

    [Theory]
    [InlineData(0)]
    [InlineData(1)]
    public void ItDrivesABallInFrontOfItTowardTheGoalItAttacks(int team)
    {
        float direction = team == 0 ? 1f : -1f;
        var fishAt = new Vector2(-400f * direction, 0f);
        var ballAt = new Vector2(-150f * direction, 0f);
        var match = Match(team, fishAt, team == 0 ? 0f : MathF.PI, ballAt);

        match.Play(40);

        // Pushed at about 300 mm/s from the third cycle on: some 900 mm in 4 s (and no goal yet).
        float gained = (match.BallAt(0).X - ballAt.X) * direction;
        Assert.True(gained > 500f, $"team {team}: the ball moved {gained} mm toward the goal it attacks in 4 s");
    }

    private static Match Match(int team, Vector2 fish, float heading, Vector2 ball) =>
        TestMatches.FromJson(string.Create(CultureInfo.InvariantCulture,
            $$"""{"fish":[{"team":{{team}},"position":[{{fish.X}},{{fish.Y}}],"heading":{{heading}},"strategy":"chase-ball"}],"balls":[{"position":[{{ball.X}},{{ball.Y}}]}]}"""));

    private static float WrapAngle(float a)
    {
        float r = MathF.IEEERemainder(a, 2f * MathF.PI);
        return r >= MathF.PI ? r - (2f * MathF.PI) : r;
    }
}
