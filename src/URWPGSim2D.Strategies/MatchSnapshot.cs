using System.Collections.Generic;

namespace URWPGSim2D.Strategies;

/// <summary>
/// The read-only picture of the match that strategies decide from: the state at the end of the
/// last cycle (with the reference's observation noise when the match has noise on). The same
/// instance is refilled every cycle; do not keep references to its spans across cycles.
/// </summary>
public sealed class MatchSnapshot
{
    private readonly FishView[] _fish;
    private readonly BallView[] _balls;
    private readonly ObstacleView[] _obstacles;
    private readonly int[] _goals = new int[4];

    internal MatchSnapshot(int fishCount, int ballCount, ObstacleView[] obstacles, float fieldLength, float fieldWidth)
    {
        _fish = new FishView[fishCount];
        _balls = new BallView[ballCount];
        _obstacles = obstacles;
        FieldLength = fieldLength;
        FieldWidth = fieldWidth;
    }

    /// <summary>Cycles completed so far (0 before the first).</summary>
    public int Cycle { get; private set; }

    /// <summary>Simulated time so far, s (Cycle × 0.1).</summary>
    public double Time => Cycle * 0.1;

    /// <summary>Field length along X, mm (X from −Length/2 to +Length/2).</summary>
    public float FieldLength { get; }

    /// <summary>Field width along Z, mm (Z from −Width/2 to +Width/2).</summary>
    public float FieldWidth { get; }

    /// <summary>Goal mouth width along Z, mm (|Z| ≤ 200).</summary>
    public float GoalWidth => 400f;

    /// <summary>Goal depth along X, mm, measured inward from each end line.</summary>
    public float GoalDepth => 150f;

    /// <summary>Every fish of the match, by index.</summary>
    public ReadOnlySpan<FishView> Fish => _fish;

    /// <summary>Every ball, by index.</summary>
    public ReadOnlySpan<BallView> Balls => _balls;

    /// <summary>Every obstacle, by index.</summary>
    public ReadOnlySpan<ObstacleView> Obstacles => _obstacles;

    /// <summary>
    /// The competition item being played (its original name, e.g. 抢球博弈), or <c>match</c> for a
    /// plain scenario.
    /// </summary>
    public string ItemName { get; private set; } = "match";

    /// <summary>
    /// The item's state for strategies, the original's <c>HtMissionVariables</c>: the original's keys
    /// and string values (integers as invariant text). Empty when the item publishes none.
    /// </summary>
    public IReadOnlyDictionary<string, string> Variables { get; private set; } = EmptyVariables;

    /// <summary>Cycles the match lasts (0 when not known in advance).</summary>
    public int TotalCycles { get; private set; }

    /// <summary>
    /// True after the half-time swap: team 0 then plays on the right (attacking −X) and team 1 on the left.
    /// </summary>
    public bool SidesSwapped { get; private set; }

    /// <summary>Teams in the match: 2, or 4 in a four-team item (teams 2 and 3 then play too).</summary>
    public int TeamCount { get; private set; } = 2;

    /// <summary>Goals scored so far by a team (the item's points in items that count points).</summary>
    /// <param name="team">0 to <see cref="TeamCount"/> − 1.</param>
    public int GoalsOf(int team) => _goals[Math.Clamp(team, 0, TeamCount - 1)];

    private static IReadOnlyDictionary<string, string> EmptyVariables { get; } = new Dictionary<string, string>();

    internal Span<FishView> FishBuffer => _fish;

    internal Span<BallView> BallBuffer => _balls;

    /// <summary>Sets the cycle and each team's score (one entry per team; fewer than two: the rest 0, more than four: ignored).</summary>
    internal void SetHeader(int cycle, ReadOnlySpan<int> goals)
    {
        Cycle = cycle;
        TeamCount = Math.Clamp(goals.Length, 2, _goals.Length);
        Array.Clear(_goals);
        goals[..Math.Min(goals.Length, _goals.Length)].CopyTo(_goals);
    }

    /// <summary>Sets what the item tells strategies (kept until set again).</summary>
    internal void SetItem(string itemName, IReadOnlyDictionary<string, string> variables, int totalCycles)
    {
        ItemName = itemName;
        Variables = variables;
        TotalCycles = totalCycles;
    }

    /// <summary>Sets whether the teams have changed sides (half time).</summary>
    internal void SetSidesSwapped(bool swapped) => SidesSwapped = swapped;

    /// <summary>A snapshot of the same match that owns its values (fish, balls, variables), equal to this one now.</summary>
    internal MatchSnapshot CreateCopy()
    {
        var copy = new MatchSnapshot(_fish.Length, _balls.Length, _obstacles, FieldLength, FieldWidth);
        copy.CopyFrom(this);
        return copy;
    }

    /// <summary>
    /// Makes this snapshot (made by <see cref="CreateCopy"/>) equal to <paramref name="source"/>: a
    /// strategy that reads it on its own thread is unaffected by the next cycle's changes to the source.
    /// </summary>
    internal void CopyFrom(MatchSnapshot source)
    {
        source._fish.CopyTo(_fish, 0);
        source._balls.CopyTo(_balls, 0);
        Cycle = source.Cycle;
        source._goals.CopyTo(_goals, 0);
        TeamCount = source.TeamCount;
        ItemName = source.ItemName;
        TotalCycles = source.TotalCycles;
        SidesSwapped = source.SidesSwapped;
        if (source.Variables.Count == 0)
        {
            Variables = EmptyVariables;
            return;
        }

        var own = Variables as OrderedVariables ?? new OrderedVariables();
        if (source.Variables is OrderedVariables ordered)
        {
            own.CopyFrom(ordered);
        }
        else
        {
            var fresh = new OrderedVariables();
            foreach (var pair in source.Variables)
            {
                fresh.Set(pair.Key, pair.Value);
            }

            own = fresh;
        }

        Variables = own;
    }
}
