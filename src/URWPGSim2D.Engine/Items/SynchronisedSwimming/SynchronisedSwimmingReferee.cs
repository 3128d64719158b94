namespace URWPGSim2D.Engine.Items.SynchronisedSwimming;

/// <summary>
/// The rules of 花样游泳, as the original's <c>MatchSynchronisedSwimming</c> and the part of its
/// <c>Mission.SetDecisionsToFishes</c> for this item: people judge the swimming, so the referee
/// keeps no score (−1, shown as "not scored") and no <c>HtMissionVariables</c>, and the match lasts
/// its time. The server drives fish 0, whatever its strategy decides: a counter starts at 400 and
/// drops by one every cycle (back to 400 after it passes below 0, so a round is 401 cycles); while
/// fish 0's centre is at least 400 mm from every wall it gets a random speed gear 0–9 and a random
/// turn gear, 8–14 (right) while the counter is 200 or more and 0–6 (left) below, drawn from the
/// match's seed; nearer a wall it gets gear 4, turn gear 1.
/// </summary>
internal sealed class SynchronisedSwimmingReferee : ItemReferee
{
    /// <summary>The counter's start and reset value.</summary>
    public const int CounterStart = 400;

    /// <summary>Counter values below this give left turns.</summary>
    public const int LeftBelow = 200;

    /// <summary>Distance from the walls inside which fish 0 swims at random, mm.</summary>
    public const float WallMargin = 400f;

    /// <summary>Fish 0's decision near a wall: speed gear 4, turn gear 1.</summary>
    public static readonly Decision NearWall = new(4, 1);

    private readonly SeededRandom _random;
    private int _counter = CounterStart;
    private int _fish0 = -1;

    /// <summary>Creates the referee of one match; fish 0's codes are drawn from <paramref name="seed"/>.</summary>
    public SynchronisedSwimmingReferee(SynchronisedSwimmingItem item, ScenarioDefinition scenario, int cycles, ulong seed)
        : base(item, scenario, cycles, halves: 1)
    {
        _random = new SeededRandom(seed ^ 0x46495348UL);
        Scores[0] = -1;
    }

    /// <summary>The index of the server-driven fish (the team's first), or −1 before the match starts.</summary>
    public int DrivenFish => _fish0;

    /// <summary>Whether a position is at least <see cref="WallMargin"/> from every wall of the field.</summary>
    public static bool AwayFromWalls(Vector2 p, float fieldLength, float fieldWidth) =>
        MathF.Abs(p.X) <= (fieldLength * 0.5f) - WallMargin && MathF.Abs(p.Y) <= (fieldWidth * 0.5f) - WallMargin;

    /// <inheritdoc/>
    public override void AfterDecisions(World world)
    {
        base.AfterDecisions(world);
        if (_fish0 < 0)
        {
            return;
        }

        _counter--;
        var f = world.Fish[_fish0];
        if (AwayFromWalls(f.Position, world.Field.Length, world.Field.Width))
        {
            int vcode = SynchronisedSwimmingLayout.Next(_random, 0, 10);
            int tcode = _counter < LeftBelow ? SynchronisedSwimmingLayout.Next(_random, 0, 7) : SynchronisedSwimmingLayout.Next(_random, 8, 15);
            f.Decision = new Decision(vcode, tcode);
        }
        else
        {
            f.Decision = NearWall;
        }

        if (_counter < 0)
        {
            _counter = CounterStart;
        }
    }

    /// <inheritdoc/>
    protected override void OnStart(World world)
    {
        foreach (var f in world.Fish)
        {
            if (f.Team == 0)
            {
                _fish0 = f.Index;
                return;
            }
        }
    }

    /// <inheritdoc/>
    protected override bool Score(World world, ReadOnlySpan<ContactRecord> contacts) => false;

    /// <inheritdoc/>
    protected override MatchOutcome Decide() => new(-1, "judged by people: no score");
}
