using System.Globalization;
using URWPGSim2D.Engine.Items.BallGrab;

namespace URWPGSim2D.Engine.Items.NewBallGrab;

/// <summary>
/// The rules of 抢球大作战, as the original's <c>NewMatch2V2BallRace</c>. After every cycle, in the
/// original's order:
/// <list type="number">
/// <item>Scores: the team playing from the left end scores the balls lying wholly in the left goal
/// box now, the other team those in the right box; a ball counts 1, the centre ball (ball 4) 3. A
/// ball entering or leaving a box is an event (<c>goal</c> / <c>out</c>). In the clutch shot the
/// first cycle the scores differ ends the match.</item>
/// <item>The period's time up: different scores end the match; equal scores after normal time start
/// the clutch shot (event <c>period</c>), 5 minutes (3000 cycles), every fish back to its start pose
/// at its current end, the balls where they are; equal scores after it: a tie.</item>
/// <item>Half time, at the middle cycle of normal time and of the clutch shot: the teams change ends
/// (every fish to the start pose of its new end) and the balls are mirrored through the centre.</item>
/// </list>
/// <c>HtMissionVariables</c>: <c>CompetitionPeriod</c> (0 normal time, 3 clutch shot).
/// </summary>
internal sealed class NewBallGrabReferee : ItemReferee, IGoalBoxGame
{
    /// <summary>Length of the clutch shot, cycles (5 minutes).</summary>
    public const int ClutchShotCycles = 3000;

    private readonly int[] _inBox;
    private int _periodStart;
    private int _periodLength;
    private bool _halfTimeDone;
    private string _rule = "higher score";

    /// <summary>Creates the referee of one match.</summary>
    public NewBallGrabReferee(NewBallGrabItem item, ScenarioDefinition scenario, int cycles)
        : base(item, scenario, cycles, halves: 1)
    {
        _inBox = new int[scenario.Balls.Count];
        _periodLength = cycles;
    }

    /// <summary>Whether the clutch shot is being played.</summary>
    public bool ClutchShot { get; private set; }

    /// <summary>The team playing from the left end now.</summary>
    public int LeftTeam { get; private set; }

    /// <inheritdoc/>
    public int Restarts { get; private set; }

    /// <inheritdoc/>
    /// <remarks>A match of no cycles (<c>--cycles 0</c>: the layout alone) plays no clutch shot either.</remarks>
    public override int MaxCycles => Cycles == 0 ? 0 : Cycles + ClutchShotCycles;

    /// <inheritdoc/>
    protected override bool PlaysOn => true;

    /// <inheritdoc/>
    public int BoxSide(int team) => team == LeftTeam ? -1 : 1;

    /// <inheritdoc/>
    public bool HasScored(int team, int ball) => _inBox[ball] == BoxSide(team);

    /// <summary>Where ball <paramref name="ball"/> lies now: −1 in the left box, +1 in the right one, 0 in neither.</summary>
    public int BoxOf(int ball) => _inBox[ball];

    /// <inheritdoc/>
    protected override bool Score(World world, ReadOnlySpan<ContactRecord> contacts)
    {
        Count(world);
        if (ClutchShot && Scores[0] != Scores[1])
        {
            _rule = "clutch shot";
            MatchDone = true;
            return false;
        }

        int elapsed = world.Cycle - _periodStart;
        if (elapsed >= _periodLength)
        {
            if (Scores[0] != Scores[1] || ClutchShot)
            {
                _rule = ClutchShot ? "tie" : "higher score";
                MatchDone = true;
                return false;
            }

            ClutchShot = true;
            _periodStart = world.Cycle;
            _periodLength = ClutchShotCycles;
            _halfTimeDone = false;
            AddEvent(world.Cycle, "period", -1, -1, -1, double.NaN, $"{Scores[0]}:{Scores[1]}, clutch shot follows");
            Restart(world);
            return true;
        }

        if (!_halfTimeDone && elapsed == _periodLength / 2)
        {
            _halfTimeDone = true;
            LeftTeam = 1 - LeftTeam;
            AddEvent(ItemEvent.Plain(world.Cycle, "half-time", ClutchShot ? "half time of the clutch shot: teams change ends" : "half 1 over: teams change ends"));
            Restart(world);
            foreach (var b in world.Balls)
            {
                Placement.Place(b, -b.Position);
            }

            // The mirrored balls lie in the other box, which is now the same team's.
            Array.Clear(_inBox);
            Count(world, events: false);
            return true;
        }

        return false;
    }

    /// <inheritdoc/>
    protected override MatchOutcome Decide() =>
        Scores[0] == Scores[1] ? new MatchOutcome(-1, "tie") : new MatchOutcome(Scores[0] > Scores[1] ? 0 : 1, _rule);

    /// <inheritdoc/>
    protected override void UpdateVariables(World world) => Variables.Set("CompetitionPeriod", ClutchShot ? 3 : 0);

    // The scores from the balls in the boxes now; events for the balls that came in or went out.
    private void Count(World world, bool events = true)
    {
        Scores[0] = Scores[1] = 0;
        for (int i = 0; i < world.Balls.Length; i++)
        {
            var b = world.Balls[i];
            int box = BallGrabLayout.InBox(b.Position, b.Radius, -1) ? -1 : BallGrabLayout.InBox(b.Position, b.Radius, 1) ? 1 : 0;
            int value = (int)BallValue(i);
            if (box != 0)
            {
                Scores[box < 0 ? LeftTeam : 1 - LeftTeam] += value;
            }

            if (events && box != _inBox[i])
            {
                if (_inBox[i] != 0)
                {
                    int loser = _inBox[i] < 0 ? LeftTeam : 1 - LeftTeam;
                    AddEvent(world.Cycle, "out", loser, -1, i, -value, $"ball {i} leaves team {loser}'s box (-{value})");
                }

                if (box != 0)
                {
                    int scorer = box < 0 ? LeftTeam : 1 - LeftTeam;
                    AddEvent(world.Cycle, "goal", scorer, -1, i, value, $"ball {i} in team {scorer}'s box (+{value})");
                }
            }

            _inBox[i] = box;
        }
    }

    // Every fish to the start pose of its team's current end; the demo strategies start afresh.
    private void Restart(World world)
    {
        Restarts++;
        int[] next = [0, 0];
        foreach (var f in world.Fish)
        {
            int end = f.Team == LeftTeam ? 0 : 1;
            var pose = StartOf(end, next[f.Team]++);
            Placement.Place(f, pose.Position, pose.Heading);
        }
    }
}
