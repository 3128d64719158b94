using System.Globalization;
using System.Runtime.CompilerServices;
using URWPGSim2D.Engine.Trace;

namespace URWPGSim2D.Engine.Items;

/// <summary>
/// The rules of one item for one match. The match calls <see cref="Start"/> before the first cycle,
/// <see cref="AfterDecisions"/> after the strategies decided (speed caps, server-driven fish) and
/// <see cref="Judge"/> after each cycle's motion: the item scores (<see cref="Score"/>), then the
/// referee ends a half when its time is up or the item says so (<see cref="HalfDone"/>), changes
/// ends (<see cref="OnHalfTime"/>) or ends the match and decides the winner (<see cref="Decide"/>),
/// and refreshes the strategies' <see cref="Variables"/>. Halves: every half but the last is
/// <see cref="HalfLength"/> = cycles / halves long; the last lasts the rest of the cycles, counted
/// from its start (a half ended early does not shorten the next one).
/// </summary>
public abstract class ItemReferee : ITraceItemInfo
{
    private readonly List<ItemEvent> _events;
    private int _traced;
    private MatchOutcome _outcome;

    /// <summary>Creates the referee.</summary>
    /// <param name="item">The item.</param>
    /// <param name="scenario">The match's layout (the item's, positions possibly overridden).</param>
    /// <param name="cycles">Cycles of the whole match (both halves).</param>
    /// <param name="halves">1 or 2.</param>
    /// <param name="eventCapacity">Room for events before the list grows (an item scoring often, many).</param>
    protected ItemReferee(CompetitionItem item, ScenarioDefinition scenario, int cycles, int halves, int eventCapacity = 32)
    {
        _events = new(eventCapacity);
        Item = item;
        Scenario = scenario;
        Cycles = cycles;
        Halves = halves;
        HalfLength = cycles / halves;
        Scores = new int[item.TeamCount];
    }

    /// <summary>The item.</summary>
    public CompetitionItem Item { get; }

    /// <summary>The match's layout.</summary>
    public ScenarioDefinition Scenario { get; }

    /// <summary>Cycles of the whole match.</summary>
    public int Cycles { get; }

    /// <summary>Number of halves (1 or 2).</summary>
    public int Halves { get; }

    /// <summary>Length of every half but the last, cycles.</summary>
    public int HalfLength { get; }

    /// <summary>The half being played, 1-based.</summary>
    public int Half { get; private set; } = 1;

    /// <summary>The cycle the current half started after (0 for the first).</summary>
    public int HalfStartCycle { get; private set; }

    /// <summary>Whether the teams play on the other side than at cycle 0 (second half of a two-half item).</summary>
    public bool SidesSwapped => Half == 2;

    /// <summary>Score per team (team 0 first).</summary>
    public int[] Scores { get; }

    /// <summary>Every event so far, in order.</summary>
    public IReadOnlyList<ItemEvent> Events => _events;

    /// <summary>The item's state for strategies, with the original's <c>HtMissionVariables</c> keys.</summary>
    public MissionVariables Variables { get; } = new();

    /// <summary>
    /// Whether events carry their text (<see cref="ItemEvent.Text"/>), on by default. Off, every
    /// event is still recorded, with an empty text that is never formatted: a cycle with a goal,
    /// a foul or half time then allocates nothing (a learning environment reads scores, not messages).
    /// </summary>
    public bool EventTexts { get; set; } = true;

    /// <summary>Whether the match is over (time, or an ending condition of the item).</summary>
    public bool IsOver { get; private set; }

    /// <summary>The result: final once <see cref="IsOver"/>, otherwise what it would be now.</summary>
    public MatchOutcome Outcome => IsOver ? _outcome : Decide();

    /// <inheritdoc/>
    string ITraceItemInfo.Slug => Item.Slug;

    /// <inheritdoc/>
    IReadOnlyList<TraceZone> ITraceItemInfo.Zones => Scenario.Zones;

    /// <summary>Set by an item when its match is decided before the time is up (e.g. all balls in).</summary>
    protected bool MatchDone { get; set; }

    /// <summary>
    /// Whether the item keeps playing when its time is up (extra periods deciding a tie): the item
    /// then ends the match itself (<see cref="MatchDone"/>) and may last up to <see cref="MaxCycles"/>.
    /// </summary>
    protected virtual bool PlaysOn => false;

    /// <summary>The most cycles the match can last: <see cref="Cycles"/>, or more for an item that plays extra periods.</summary>
    public virtual int MaxCycles => Cycles;

    /// <summary>What half time changes, for its event's text (default "teams change ends").</summary>
    protected virtual string HalfTimeChange => "teams change ends";

    /// <summary>Whether the current half is over before its time (e.g. three catches).</summary>
    protected virtual bool HalfDone => false;

    /// <summary>The points of a ball in this item, or NaN when balls have no value.</summary>
    public double BallValue(int ball) => ball < Scenario.BallValues.Count ? Scenario.BallValues[ball] : double.NaN;

    /// <inheritdoc/>
    double? ITraceItemInfo.BallValue(int ball) => ball < Scenario.BallValues.Count ? Scenario.BallValues[ball] : null;

    /// <inheritdoc/>
    double ITraceItemInfo.Score(int team) => team < Scores.Length ? Scores[team] : 0;

    /// <inheritdoc/>
    void ITraceItemInfo.AddEvents(int cycle, List<TraceEvent> events)
    {
        for (; _traced < _events.Count && _events[_traced].Cycle <= cycle; _traced++)
        {
            var e = _events[_traced];
            if (e.Cycle == cycle)
            {
                events.Add(new TraceEvent(e.Kind, e.Text, e.Team >= 0 ? e.Team : null, e.Fish >= 0 ? e.Fish : null, e.Ball >= 0 ? e.Ball : null, double.IsNaN(e.Value) ? null : e.Value));
            }
        }
    }

    /// <summary>Prepares the bodies for cycle 1 (parks frozen fish) and fills <see cref="Variables"/>.</summary>
    public void Start(World world)
    {
        OnStart(world);
        UpdateVariables(world);
    }

    /// <summary>Whether <see cref="RestartInPlace"/> can put this item's referee back to the state of a new one.</summary>
    internal virtual bool CanRestart => false;

    /// <summary>
    /// Back to the state of a new referee of the same match, its lists and arrays kept (no event, no
    /// score, first half), then <see cref="Start"/> on <paramref name="world"/> (whose bodies are back at
    /// their start poses): a match restarted in place.
    /// </summary>
    /// <exception cref="InvalidOperationException">The item's referee cannot restart (<see cref="CanRestart"/>).</exception>
    internal void RestartInPlace(World world)
    {
        if (!CanRestart)
        {
            throw new InvalidOperationException($"the referee of {Item.Slug} cannot restart in place");
        }

        _events.Clear();
        _traced = 0;
        _outcome = default;
        Half = 1;
        HalfStartCycle = 0;
        Array.Clear(Scores);
        IsOver = false;
        MatchDone = false;
        OnRestart();
        Start(world);
    }

    /// <summary>Back to the item's own state of a new referee (<see cref="RestartInPlace"/>).</summary>
    private protected virtual void OnRestart()
    {
    }

    /// <summary>After the strategies decided: caps, frozen and server-driven fish.</summary>
    public virtual void AfterDecisions(World world)
    {
        foreach (var f in world.Fish)
        {
            if (f.OutOfPlay)
            {
                f.Decision = URWPGSim2D.Strategies.Decision.Stop;
            }
        }
    }

    /// <summary>Applies the rules after a cycle's motion; returns true when bodies were moved by the rules (overlaps must be settled).</summary>
    public bool Judge(World world, ReadOnlySpan<ContactRecord> contacts)
    {
        if (IsOver)
        {
            return false;
        }

        bool moved = Score(world, contacts);
        int length = Half < Halves ? HalfLength : Cycles - ((Halves - 1) * HalfLength);
        if (MatchDone || HalfDone || (!PlaysOn && world.Cycle - HalfStartCycle >= length))
        {
            if (Half < Halves && !MatchDone)
            {
                AddEvent(world.Cycle, "half-time", -1, -1, -1, double.NaN, $"half {Half} over: {HalfTimeChange}");
                Half++;
                HalfStartCycle = world.Cycle;
                moved |= OnHalfTime(world);
            }
            else
            {
                IsOver = true;
                _outcome = Decide();
                if (_outcome.Winner >= 0)
                {
                    AddEvent(world.Cycle, "end", _outcome.Winner, -1, -1, double.NaN, $"match over: team {_outcome.Winner} wins ({_outcome.Rule})");
                }
                else
                {
                    AddEvent(world.Cycle, "end", -1, -1, -1, double.NaN, $"match over: {_outcome.Rule}");
                }
            }
        }

        UpdateVariables(world);
        return moved;
    }

    /// <summary>Records an event of the current cycle.</summary>
    protected void AddEvent(in ItemEvent e) => _events.Add(e);

    /// <summary>Records an event of the current cycle whose text is formatted (invariant culture) only when <see cref="EventTexts"/> is on, and is empty otherwise.</summary>
    private protected void AddEvent(int cycle, string kind, int team, int fish, int ball, double value, [InterpolatedStringHandlerArgument("")] ref EventText text) =>
        _events.Add(new ItemEvent(cycle, kind, team, fish, ball, value, text.ToStringAndClear()));

    /// <summary>Prepares cycle 1 (default: nothing).</summary>
    protected virtual void OnStart(World world)
    {
    }

    /// <summary>Scores this cycle; returns true when it moved bodies.</summary>
    protected abstract bool Score(World world, ReadOnlySpan<ContactRecord> contacts);

    /// <summary>Changes ends at half time; returns true when it moved bodies.</summary>
    protected virtual bool OnHalfTime(World world) => false;

    /// <summary>The result from the current state.</summary>
    protected abstract MatchOutcome Decide();

    /// <summary>The scenario's <paramref name="n"/>-th fish (0-based) of <paramref name="team"/>: its start pose at cycle 0.</summary>
    /// <exception cref="InvalidOperationException">The team has fewer fish.</exception>
    protected FishDefinition StartOf(int team, int n)
    {
        int k = n;
        foreach (var f in Scenario.Fish)
        {
            if (f.Team == team && k-- == 0)
            {
                return f;
            }
        }

        throw new InvalidOperationException(string.Create(CultureInfo.InvariantCulture, $"team {team} has no fish {n}"));
    }

    /// <summary>Refreshes <see cref="Variables"/> from the current state.</summary>
    protected virtual void UpdateVariables(World world)
    {
    }
}
