using System.Globalization;

namespace URWPGSim2D.Engine.Items.CrossCountry;

/// <summary>
/// The rules of 障碍越野, as the original's <c>MatchObstacleRacing</c>: four steps in order, at most
/// one per cycle — the fish touches ball 0 (event <c>touch</c>), ball 0's centre comes within 22 mm
/// of target 0 (squared distance ≤ 484; event <c>target</c>, +1), the fish touches ball 1, ball 1
/// comes within 22 mm of target 1 (+1) — and the match ends after the last. A ball reaching its
/// target before its step does not count (the original checks only the current step). The score
/// is the number of balls home; the step cycles are kept for the summary. No
/// <c>HtMissionVariables</c> (the original publishes none).
/// </summary>
internal sealed class CrossCountryReferee : ItemReferee
{
    private readonly int[] _stepCycle = [0, 0, 0, 0];

    /// <summary>Creates the referee of one match.</summary>
    public CrossCountryReferee(CrossCountryItem item, ScenarioDefinition scenario, int cycles)
        : base(item, scenario, cycles, halves: 1)
    {
    }

    /// <summary>Steps done: 0 none, 1 ball 0 touched, 2 ball 0 home, 3 ball 1 touched, 4 ball 1 home.</summary>
    public int Step { get; private set; }

    /// <summary>The cycle step <paramref name="step"/> (1–4) was done in, or 0.</summary>
    public int StepCycle(int step) => _stepCycle[step - 1];

    /// <summary>The ball of the current step (0 until ball 0 is home, then 1).</summary>
    public int CurrentBall => Step < 2 ? 0 : 1;

    /// <inheritdoc/>
    protected override bool Score(World world, ReadOnlySpan<ContactRecord> contacts)
    {
        if (Step >= 4)
        {
            return false;
        }

        int ball = CurrentBall;
        if (Step % 2 == 0)
        {
            foreach (ref readonly var c in contacts)
            {
                if (c.Pair.Kind == PairKind.FishBall && c.Pair.B == ball)
                {
                    Done(world.Cycle);
                    AddEvent(world.Cycle, "touch", 0, c.Pair.A, ball, double.NaN, $"the fish touches ball {ball}");
                    break;
                }
            }
        }
        else if (CrossCountryLayout.AtTarget(world.Balls[ball].Position, CrossCountryLayout.Targets[ball]))
        {
            Scores[0]++;
            Done(world.Cycle);
            AddEvent(world.Cycle, "target", 0, -1, ball, 1, $"ball {ball} reaches its target (+1)");
            MatchDone = Step == 4;
        }

        return false;
    }

    /// <inheritdoc/>
    protected override MatchOutcome Decide() => Step == 4
        ? new MatchOutcome(0, string.Create(CultureInfo.InvariantCulture, $"course completed in {_stepCycle[3] / 10.0:0.0} s"))
        : new MatchOutcome(-1, string.Create(CultureInfo.InvariantCulture, $"course not completed ({Step} of 4 steps)"));

    private void Done(int cycle)
    {
        _stepCycle[Step] = cycle;
        Step++;
    }
}
