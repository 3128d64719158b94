using System.Globalization;

namespace URWPGSim2D.Engine.Items.Snooker;

/// <summary>
/// The rules of 斯诺克, as the original's <c>MatchSnooker</c>. After every cycle the first ball (by
/// id) lying in a pocket is judged (at most one per cycle). The first pot must be a red; while reds
/// remain, a pot is good when it alternates with the previous pot (red after colour, colour after
/// red; the previous pot counts even when it was wrong); once the reds are gone, only the lowest
/// colour left is good. A good red scores 1 and is laid off the table beside the left pockets
/// (out of play); a good colour scores id − 4 and is re-spotted while reds remain, laid off the
/// table beside the right pockets after. A wrong red goes back against the right wall (top
/// pocket) or the left wall (bottom pocket) at z = 0; a wrong colour is re-spotted. Events:
/// <c>ball-in-hole</c> (value = points, 0 when wrong). The match ends when every ball is down.
/// <c>HtMissionVariables</c>: <c>BallsInFieldFlag</c>, bit i set while ball i is on the table.
/// </summary>
internal sealed class SnookerReferee : ItemReferee
{
    private const int AllBalls = (1 << SnookerLayout.BallCount) - 1;
    private const int RedBits = (1 << SnookerLayout.Reds) - 1;
    private readonly int[] _laidRed = [0, 0];
    private readonly int[] _laidColour = [0, 0];

    /// <summary>Creates the referee of one match.</summary>
    public SnookerReferee(SnookerItem item, ScenarioDefinition scenario, int cycles)
        : base(item, scenario, cycles, halves: 1)
    {
    }

    /// <summary>Bit i is set while ball i is on the table (the original's <c>BallsInFieldFlag</c>, 0x3FF at the start).</summary>
    public int BallsInField { get; private set; } = AllBalls;

    /// <summary>The id of the last ball potted (good or wrong), or −1.</summary>
    public int LastPotted { get; private set; } = -1;

    /// <summary>The cycle of the last good pot, or 0.</summary>
    public int LastGoodPotCycle { get; private set; }

    /// <summary>Whether reds are still on the table.</summary>
    public bool RedsLeft => (BallsInField & RedBits) != 0;

    /// <summary>Whether potting <paramref name="ball"/> now would be good.</summary>
    public bool IsGood(int ball)
    {
        if (LastPotted < 0)
        {
            return ball < SnookerLayout.Reds;
        }

        if (RedsLeft)
        {
            return (ball < SnookerLayout.Reds) != (LastPotted < SnookerLayout.Reds);
        }

        return ball >= SnookerLayout.Reds && ball == LowestColourLeft();
    }

    /// <inheritdoc/>
    protected override bool Score(World world, ReadOnlySpan<ContactRecord> contacts)
    {
        for (int i = 0; i < world.Balls.Length && i < SnookerLayout.BallCount; i++)
        {
            var b = world.Balls[i];
            int row = b.OutOfPlay ? 0 : SnookerLayout.Pocket(b.Position);
            if (row != 0)
            {
                Pot(world, b, row);
                return true;
            }
        }

        return false;
    }

    /// <inheritdoc/>
    protected override MatchOutcome Decide() => BallsInField == 0
        ? new MatchOutcome(0, "every ball potted")
        : new MatchOutcome(-1, string.Create(CultureInfo.InvariantCulture, $"time up with {System.Numerics.BitOperations.PopCount((uint)BallsInField)} balls on the table"));

    /// <inheritdoc/>
    protected override void UpdateVariables(World world) => Variables.Set("BallsInFieldFlag", BallsInField);

    private void Pot(World world, BallState b, int row)
    {
        int id = b.Index;
        bool red = id < SnookerLayout.Reds;
        bool good = IsGood(id);
        LastPotted = id;
        int points = 0;
        if (good)
        {
            points = SnookerLayout.Value(id);
            Scores[0] += points;
            LastGoodPotCycle = world.Cycle;
            int side = row < 0 ? 0 : 1;
            if (red)
            {
                BallsInField &= ~(1 << id);
                Placement.Park(b, SnookerLayout.PottedRedPlace(_laidRed[side]++, row));
            }
            else if (RedsLeft)
            {
                Placement.Place(b, SnookerLayout.Spot(id));
            }
            else
            {
                BallsInField &= ~(1 << id);
                Placement.Park(b, SnookerLayout.PottedColourPlace(_laidColour[side]++, row));
            }
        }
        else
        {
            Placement.Place(b, red ? SnookerLayout.FoulRedPlace(row) : SnookerLayout.Spot(id));
        }

        string what = good ? string.Create(CultureInfo.InvariantCulture, $"+{points}") : "wrong ball, no score";
        AddEvent(world.Cycle, "ball-in-hole", 0, -1, id, points, $"{(red ? "red" : "colour")} ball {id} potted ({what})");
        MatchDone = BallsInField == 0;
    }

    private int LowestColourLeft()
    {
        for (int i = SnookerLayout.Reds; i < SnookerLayout.BallCount; i++)
        {
            if ((BallsInField & (1 << i)) != 0)
            {
                return i;
            }
        }

        return -1;
    }
}
