using System.Globalization;

namespace URWPGSim2D.Engine.Items.Transport;

/// <summary>
/// The rules of 水中搬运, as the original's <c>Match1V1Moving</c>: after every cycle each ball i
/// whose centre is less than 22 mm from hole i's centre scores 1, once per ball (event
/// <c>ball-in-hole</c>; the ball stays in play, and leaving the hole does not take the point back).
/// The match ends when all six are in or the time is up; the cycle of the last ball in is the
/// result's time. <c>HtMissionVariables</c>: <c>Ball0InHole</c> … <c>Ball5InHole</c>, 0 or 1.
/// </summary>
internal sealed class TransportReferee : ItemReferee
{
    private static readonly string[] Keys = ["Ball0InHole", "Ball1InHole", "Ball2InHole", "Ball3InHole", "Ball4InHole", "Ball5InHole"];

    private readonly bool[] _inHole = new bool[TransportLayout.Count];

    /// <summary>Creates the referee of one match.</summary>
    public TransportReferee(TransportItem item, ScenarioDefinition scenario, int cycles)
        : base(item, scenario, cycles, halves: 1)
    {
    }

    /// <summary>The cycle the last ball went in, or 0 if none has.</summary>
    public int LastGoalCycle { get; private set; }

    /// <summary>Whether ball <paramref name="ball"/> has been in its hole.</summary>
    public bool InHole(int ball) => _inHole[ball];

    /// <inheritdoc/>
    protected override bool Score(World world, ReadOnlySpan<ContactRecord> contacts)
    {
        for (int i = 0; i < TransportLayout.Count && i < world.Balls.Length; i++)
        {
            if (_inHole[i] || !TransportLayout.InHole(world.Balls[i].Position, TransportLayout.Holes[i]))
            {
                continue;
            }

            _inHole[i] = true;
            Scores[0]++;
            LastGoalCycle = world.Cycle;
            AddEvent(world.Cycle, "ball-in-hole", 0, -1, i, 1, $"ball {i} in hole {i} (+1)");
        }

        MatchDone = Scores[0] == TransportLayout.Count;
        return false;
    }

    /// <inheritdoc/>
    protected override MatchOutcome Decide() => Scores[0] switch
    {
        TransportLayout.Count => new MatchOutcome(0, string.Create(CultureInfo.InvariantCulture, $"all 6 balls in, the last at {LastGoalCycle / 10.0:0.0} s")),
        0 => new MatchOutcome(-1, "no ball in its hole"),
        _ => new MatchOutcome(-1, string.Create(CultureInfo.InvariantCulture, $"{Scores[0]} of 6 balls in, the last at {LastGoalCycle / 10.0:0.0} s")),
    };

    /// <inheritdoc/>
    protected override void UpdateVariables(World world)
    {
        for (int i = 0; i < Keys.Length; i++)
        {
            Variables.Set(Keys[i], _inHole[i] ? 1 : 0);
        }
    }
}
