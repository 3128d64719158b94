using System.Globalization;

namespace URWPGSim2D.Engine.Items.PushBallViaChannel;

/// <summary>
/// The rules of 协作过孔, as the original's <c>TwoFishPushBallViaChannel</c>. After each cycle, in the
/// original's order:
/// <list type="number">
/// <item>A fish touching the ball is marked as having touched it in the stage being played
/// (<see cref="Stage"/>, 1–4).</item>
/// <item>For each of the lines the ball passes (walls 0–2's left faces x 600, −75, −750, then the left
/// goal line −1350; the ball is past when centre + 58 &lt; the line): once the ball is past line i,
/// stage i scores 1 if both fish touched the ball during stage i (event <c>stage</c>), and the stage
/// being played becomes i + 1 (the furthest line the ball is past now decides it).</item>
/// <item>The ball past the goal line ends the match (event <c>through</c>); so does the time.</item>
/// </list>
/// The score is the sum of the four stages' points. <c>HtMissionVariables</c>:
/// <c>IsCollidedBallAndFish{0,1}AtStage{1..4}</c> ("True" / "False", as .NET writes a bool) and
/// <c>ExecutingTaskNo</c> (1–4).
/// </summary>
internal sealed class PushBallViaChannelReferee : ItemReferee
{
    private static readonly string[,] TouchKeys = CreateKeys();

    private readonly bool[,] _touched = new bool[2, 4];
    private readonly bool[] _stageScore = new bool[4];
    private readonly bool[] _passed = new bool[4];
    private readonly int[] _scoreCycle = new int[5];

    /// <summary>Creates the referee of one match.</summary>
    public PushBallViaChannelReferee(PushBallViaChannelItem item, ScenarioDefinition scenario, int cycles)
        : base(item, scenario, cycles, halves: 1)
    {
    }

    /// <summary>The stage being played (the original's <c>ExecutingTaskNo</c>), 1–4.</summary>
    public int Stage { get; private set; } = 1;

    /// <summary>The cycle the ball got into the left goal, or 0.</summary>
    public int ThroughCycle { get; private set; }

    /// <summary>Whether fish <paramref name="fish"/> (0 or 1) touched the ball during stage <paramref name="stage"/> (1–4).</summary>
    public bool Touched(int fish, int stage) => _touched[fish, stage - 1];

    /// <summary>Whether stage <paramref name="stage"/> (1–4) scored.</summary>
    public bool StageScored(int stage) => _stageScore[stage - 1];

    /// <summary>The cycle the score first reached <paramref name="score"/> (1–4), or 0.</summary>
    public int ScoreCycle(int score) => _scoreCycle[score];

    /// <inheritdoc/>
    protected override bool Score(World world, ReadOnlySpan<ContactRecord> contacts)
    {
        foreach (ref readonly var c in contacts)
        {
            if (c.Pair.Kind == PairKind.FishBall && (uint)c.Pair.A < 2)
            {
                _touched[c.Pair.A, Stage - 1] = true;
            }
        }

        var ball = world.Balls[0];
        float right = ball.Position.X + ball.Radius;
        var lines = PushBallViaChannelLayout.StageLines;
        for (int i = 0; i < lines.Length; i++)
        {
            if (right >= lines[i])
            {
                continue;
            }

            bool scores = _touched[0, i] && _touched[1, i];
            _stageScore[i] |= scores;
            if (i < 3)
            {
                Stage = i + 2;
            }

            if (!_passed[i])
            {
                _passed[i] = true;
                string touched = scores ? " after both fish touched it (+1)" : ", not touched by both fish in this stage (+0)";
                if (i < 3)
                {
                    AddEvent(world.Cycle, "stage", 0, -1, 0, scores ? 1 : 0, $"stage {i + 1}: the ball is past wall {i}{touched}");
                }
                else
                {
                    AddEvent(world.Cycle, "stage", 0, -1, 0, scores ? 1 : 0, $"stage {i + 1}: the ball is in the left goal{touched}");
                }
            }

            if (i == 3 && ThroughCycle == 0)
            {
                ThroughCycle = world.Cycle;
                AddEvent(new ItemEvent(world.Cycle, "through", 0, -1, 0, double.NaN, "the ball is in the left goal"));
                MatchDone = true;
            }
        }

        int score = 0;
        foreach (bool s in _stageScore)
        {
            score += s ? 1 : 0;
        }

        if (score > Scores[0])
        {
            for (int k = Scores[0] + 1; k <= score; k++)
            {
                _scoreCycle[k] = world.Cycle;
            }

            Scores[0] = score;
        }

        return false;
    }

    /// <inheritdoc/>
    protected override MatchOutcome Decide()
    {
        int score = Scores[0];
        string when = score > 0 ? string.Create(CultureInfo.InvariantCulture, $", score {score} reached in {_scoreCycle[score] / 10.0:0.0} s") : string.Empty;
        return ThroughCycle > 0
            ? new MatchOutcome(0, string.Create(CultureInfo.InvariantCulture, $"ball in the left goal in {ThroughCycle / 10.0:0.0} s ({score} of 4 stages scored{when})"))
            : new MatchOutcome(-1, string.Create(CultureInfo.InvariantCulture, $"ball not in the left goal ({score} of 4 stages scored{when})"));
    }

    /// <inheritdoc/>
    protected override void UpdateVariables(World world)
    {
        for (int stage = 0; stage < 4; stage++)
        {
            for (int fish = 0; fish < 2; fish++)
            {
                Variables.Set(TouchKeys[fish, stage], _touched[fish, stage] ? bool.TrueString : bool.FalseString);
            }
        }

        Variables.Set("ExecutingTaskNo", Stage);
    }

    private static string[,] CreateKeys()
    {
        var keys = new string[2, 4];
        for (int stage = 0; stage < 4; stage++)
        {
            for (int fish = 0; fish < 2; fish++)
            {
                keys[fish, stage] = string.Create(CultureInfo.InvariantCulture, $"IsCollidedBallAndFish{fish}AtStage{stage + 1}");
            }
        }

        return keys;
    }
}
