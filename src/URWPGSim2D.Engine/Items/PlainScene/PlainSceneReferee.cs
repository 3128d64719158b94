using System.Globalization;

namespace URWPGSim2D.Engine.Items.PlainScene;

/// <summary>
/// The goal rule of the plain scene: a ball wholly inside a goal mouth is a goal. Team 0 attacks
/// the right goal (+X) and team 1 the left goal (−X), so a ball in the right goal scores for team
/// 0 and a ball in the left goal for team 1. The goal is an event (kind <c>goal</c>, worth 1) and
/// the ball goes back to its start at rest. The match plays every cycle asked for: the plain
/// scene never ends it, and the higher score wins.
/// </summary>
internal sealed class PlainSceneReferee : ItemReferee
{
    // Goal texts by team and ball, made once per process (a goal during a match allocates nothing).
    private static readonly string?[][] Texts = [new string?[64], new string?[64]];

    /// <summary>Creates the referee of a plain match.</summary>
    /// <param name="cycles">Cycles of the match.</param>
    public PlainSceneReferee(int cycles)
        : base(PlainScene.Instance, new ScenarioDefinition(), cycles, halves: 1, eventCapacity: 256)
    {
    }

    /// <inheritdoc/>
    protected override bool PlaysOn => true;

    /// <inheritdoc/>
    protected override bool Score(World world, ReadOnlySpan<ContactRecord> contacts)
    {
        bool moved = false;
        foreach (var b in world.Balls)
        {
            if (!world.Field.IsInGoal(b.Shape, out int side))
            {
                continue;
            }

            int team = World.ScoringTeam(side);
            Scores[team]++;
            AddEvent(new ItemEvent(world.Cycle, "goal", team, -1, b.Index, 1.0, Text(team, b.Index)));
            b.Position = b.StartPosition;
            b.Velocity = Vector2.Zero;
            moved = true;
        }

        return moved;
    }

    // "team T scores ball B" (cached for the first 64 balls; two threads may both make one, which is harmless).
    private static string Text(int team, int ball)
    {
        string?[] texts = Texts[team];
        if (ball >= texts.Length)
        {
            return string.Create(CultureInfo.InvariantCulture, $"team {team} scores ball {ball}");
        }

        return texts[ball] ??= string.Create(CultureInfo.InvariantCulture, $"team {team} scores ball {ball}");
    }

    /// <inheritdoc/>
    protected override MatchOutcome Decide() => MatchOutcome.ByScore(Scores[0], Scores[1], () => new MatchOutcome(-1, "tie"));
}
