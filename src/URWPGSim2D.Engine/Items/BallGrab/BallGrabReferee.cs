using System.Globalization;

namespace URWPGSim2D.Engine.Items.BallGrab;

/// <summary>
/// The rules of 抢球博弈. After every cycle each ball wholly inside a goal box scores its value for
/// the team playing from that end, once per team and ball (a team's record of the balls it has
/// scored goes with it when the ends change). Half time: every fish back to a start pose of its
/// new end, the balls mirrored through the centre (x, z → −x, −z) at rest. At the end the higher
/// score wins; equal non-zero scores go to the team that scored first (its first scoring cycle is
/// earlier); otherwise a tie. Variables: CompetitionPeriod (0, normal time) and
/// Ball_{i}_Left_Status / Ball_{i}_Right_Status (1 once the team now at the left / right end has
/// scored ball i).
/// </summary>
internal sealed class BallGrabReferee : ItemReferee, IGoalBoxGame
{
    private readonly bool[,] _scored;
    private readonly int[] _firstScoreCycle = [0, 0];
    private readonly string[] _leftKeys;
    private readonly string[] _rightKeys;

    /// <summary>Creates the referee of one match.</summary>
    public BallGrabReferee(BallGrabItem item, ScenarioDefinition scenario, int cycles)
        : base(item, scenario, cycles, halves: 2)
    {
        int balls = scenario.Balls.Count;
        _scored = new bool[2, balls];
        _leftKeys = new string[balls];
        _rightKeys = new string[balls];
        for (int i = 0; i < balls; i++)
        {
            _leftKeys[i] = string.Create(CultureInfo.InvariantCulture, $"Ball_{i}_Left_Status");
            _rightKeys[i] = string.Create(CultureInfo.InvariantCulture, $"Ball_{i}_Right_Status");
        }
    }

    /// <summary>The team playing from the left end now.</summary>
    public int LeftTeam => SidesSwapped ? 1 : 0;

    /// <inheritdoc/>
    public int Restarts => Half;

    /// <summary>The end (−1 left, +1 right) whose goal box scores for <paramref name="team"/> now.</summary>
    public int BoxSide(int team) => team == LeftTeam ? -1 : 1;

    /// <summary>Whether <paramref name="team"/> has scored ball <paramref name="ball"/>.</summary>
    public bool HasScored(int team, int ball) => _scored[team, ball];

    /// <summary>The cycle of a team's first score, or 0.</summary>
    public int FirstScoreCycle(int team) => _firstScoreCycle[team];

    /// <inheritdoc/>
    protected override bool Score(World world, ReadOnlySpan<ContactRecord> contacts)
    {
        for (int i = 0; i < world.Balls.Length; i++)
        {
            var b = world.Balls[i];
            for (int team = 0; team < 2; team++)
            {
                if (_scored[team, i] || !BallGrabLayout.InBox(b.Position, b.Radius, BoxSide(team)))
                {
                    continue;
                }

                _scored[team, i] = true;
                int value = (int)BallValue(i);
                if (Scores[team] == 0)
                {
                    _firstScoreCycle[team] = world.Cycle;
                }

                Scores[team] += value;
                AddEvent(world.Cycle, "goal", team, -1, i, value, $"team {team} scores ball {i} (+{value})");
            }
        }

        return false;
    }

    /// <inheritdoc/>
    protected override bool OnHalfTime(World world)
    {
        // Team t's fish j takes the start pose of the other team's fish j (the other end).
        int[] next = [0, 0];
        for (int i = 0; i < world.Fish.Length; i++)
        {
            var f = world.Fish[i];
            int other = 1 - f.Team;
            int k = next[f.Team]++;
            var pose = StartOf(other, k);
            Placement.Place(f, pose.Position, pose.Heading);
        }

        foreach (var b in world.Balls)
        {
            Placement.Place(b, -b.Position);
        }

        return true;
    }

    /// <inheritdoc/>
    protected override MatchOutcome Decide() => MatchOutcome.ByScore(Scores[0], Scores[1], () =>
    {
        if (Scores[0] == 0)
        {
            return new MatchOutcome(-1, "tie (no score)");
        }

        int a = _firstScoreCycle[0], b = _firstScoreCycle[1];
        return a == b ? new MatchOutcome(-1, "tie (equal scores, first scores in the same cycle)")
            : new MatchOutcome(a < b ? 0 : 1, "equal scores, earlier first score");
    });

    /// <inheritdoc/>
    protected override void UpdateVariables(World world)
    {
        Variables.Set("CompetitionPeriod", 0);
        int left = LeftTeam;
        for (int i = 0; i < _leftKeys.Length; i++)
        {
            Variables.Set(_leftKeys[i], _scored[left, i] ? 1 : 0);
        }

        for (int i = 0; i < _rightKeys.Length; i++)
        {
            Variables.Set(_rightKeys[i], _scored[1 - left, i] ? 1 : 0);
        }
    }
}
