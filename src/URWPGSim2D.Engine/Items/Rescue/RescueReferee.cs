using System.Globalization;

namespace URWPGSim2D.Engine.Items.Rescue;

/// <summary>
/// The rules of 急速救援, as the original's <c>MatchRescue</c>. Team 0 rescues in the first half,
/// team 1 in the second. After every cycle: the rescuing team's first contact with either ball is
/// its touch (time noted, event <c>touch</c>); a ball whose centre lies in the rescue zone
/// (x ∈ [1850, 2250], z ∈ [−500, 500]) scores 1 for the rescuing team, once per ball and team
/// (event <c>rescue</c>). The half ends at two rescues or when its time is up; at half time every
/// fish takes the other role's start pose (the defender's second fish is parked at (−2115, 1591),
/// out of play) and the balls go back to their starts. Equal scores: the earlier second rescue, then
/// the earlier first rescue, then the earlier first touch wins, each timed from the start of the
/// team's half (a team that never reached a mark loses to one that did). No
/// <c>HtMissionVariables</c> (the original publishes none).
/// </summary>
internal sealed class RescueReferee : ItemReferee
{
    private const int Never = int.MaxValue;

    // Per team: [0] first touch, [1] first rescue, [2] second rescue, in cycles from the start of its half.
    private readonly int[][] _times = [[Never, Never, Never], [Never, Never, Never]];
    private readonly bool[,] _rescued = new bool[2, 2];

    /// <summary>Creates the referee of one match.</summary>
    public RescueReferee(RescueItem item, ScenarioDefinition scenario, int cycles)
        : base(item, scenario, cycles, halves: 2)
    {
    }

    /// <summary>The team rescuing in the current half (0 first, then 1).</summary>
    public int Rescuer => SidesSwapped ? 1 : 0;

    /// <summary>Whether a team has rescued a ball.</summary>
    public bool HasRescued(int team, int ball) => _rescued[team, ball];

    /// <summary>A team's mark in cycles from the start of its half (0 first touch, 1 first rescue, 2 second rescue), or null if not reached.</summary>
    public int? Time(int team, int mark) => _times[team][mark] == Never ? null : _times[team][mark];

    /// <inheritdoc/>
    protected override bool HalfDone => Scores[Rescuer] >= 2;

    /// <inheritdoc/>
    protected override void OnStart(World world) => PlaceAll(world);

    /// <inheritdoc/>
    protected override bool Score(World world, ReadOnlySpan<ContactRecord> contacts)
    {
        int team = Rescuer;
        int elapsed = world.Cycle - HalfStartCycle;
        if (_times[team][0] == Never)
        {
            foreach (ref readonly var c in contacts)
            {
                if (c.Pair.Kind == PairKind.FishBall && world.Fish[c.Pair.A].Team == team && !world.Fish[c.Pair.A].OutOfPlay)
                {
                    _times[team][0] = elapsed;
                    AddEvent(world.Cycle, "touch", team, c.Pair.A, c.Pair.B, double.NaN, $"team {team} first touches ball {c.Pair.B}");
                    break;
                }
            }
        }

        for (int i = 0; i < world.Balls.Length && i < 2; i++)
        {
            if (_rescued[team, i] || !RescueLayout.InZone(world.Balls[i].Position))
            {
                continue;
            }

            _rescued[team, i] = true;
            Scores[team]++;
            _times[team][Math.Min(Scores[team], 2)] = elapsed;
            AddEvent(world.Cycle, "rescue", team, -1, i, 1, $"team {team} rescues ball {i} (+1)");
        }

        return false;
    }

    /// <inheritdoc/>
    protected override bool OnHalfTime(World world)
    {
        PlaceAll(world);
        return true;
    }

    /// <inheritdoc/>
    protected override MatchOutcome Decide() => MatchOutcome.ByScore(Scores[0], Scores[1], () =>
    {
        string[] marks = ["earlier second rescue", "earlier first rescue", "earlier first touch"];
        for (int k = 0; k < 3; k++)
        {
            int mark = 2 - k;
            int a = _times[0][mark], b = _times[1][mark];
            if (a != b)
            {
                return new MatchOutcome(a < b ? 0 : 1, "equal scores, " + marks[k]);
            }
        }

        return new MatchOutcome(-1, "tie");
    });

    // Every fish at the cycle-0 pose of the role its team has now (the team that rescues takes the
    // scenario's team-0 poses, the other team team 1's); the defender's fish 1 is parked; balls at their starts.
    private void PlaceAll(World world)
    {
        int[] next = [0, 0];
        for (int i = 0; i < world.Fish.Length; i++)
        {
            var f = world.Fish[i];
            int k = next[f.Team]++;
            int role = f.Team == Rescuer ? 0 : 1;
            var start = StartOf(role, k);
            if (role == 1 && k >= 1)
            {
                Placement.Park(f, start.Position, start.Heading);
            }
            else
            {
                Placement.Place(f, start.Position, start.Heading);
            }
        }

        for (int i = 0; i < world.Balls.Length; i++)
        {
            Placement.Place(world.Balls[i], Scenario.Balls[i].Position);
        }
    }
}
