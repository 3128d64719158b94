using System.Globalization;

namespace URWPGSim2D.Engine.Items.PushBallAvoidObstacles;

/// <summary>
/// The rules of 带球避障, as the original's <c>SingleFishPushBallAvoidObstacles</c>. After each
/// cycle, in the original's order:
/// <list type="number">
/// <item>Legs, at most one per cycle (event <c>leg</c>, +1): 1 — the fish's x passes obstacle 0's
/// x + 160 (−320); 2 — passes obstacle 9's x + 160 (640); 3 — back below obstacle 9's x − 160 (320)
/// with the ball below its x − 2 × 58 (364); 4 — below obstacle 0's x − 160 (−640) with the ball below
/// −480 − 116 (−596).</item>
/// <item>Fouls, unless one was called in the last 10 cycles (1 s; checks resume 11 cycles after a
/// foul): the fish touching an obstacle costs 5 s (50 cycles off the time) and puts the fish back at
/// the start of the leg it is on; else the ball touching an obstacle costs 3 s (30 cycles) and puts the
/// ball back at (1030, 0) — at (0, 0) on the last leg (events <c>foul</c>).</item>
/// <item>The ball wholly past the black line (centre + 58 ≤ −500) ends the match: done
/// (event <c>through</c>).</item>
/// <item>The time, less the penalties, up ends the match.</item>
/// </list>
/// The score is the number of legs done. The original publishes no <c>HtMissionVariables</c>.
/// </summary>
internal sealed class PushBallAvoidObstaclesReferee : ItemReferee
{
    /// <summary>Cycles a fish foul takes off the time (5 s).</summary>
    public const int FishFoulCycles = 50;

    /// <summary>Cycles a ball foul takes off the time (3 s).</summary>
    public const int BallFoulCycles = 30;

    /// <summary>Cycles after a foul during which no foul is called (1 s).</summary>
    public const int QuietCycles = 10;

    private readonly int[] _legCycle = [0, 0, 0, 0];
    private bool _quiet;
    private int _quietSince;

    /// <summary>Creates the referee of one match.</summary>
    public PushBallAvoidObstaclesReferee(PushBallAvoidObstaclesItem item, ScenarioDefinition scenario, int cycles)
        : base(item, scenario, cycles, halves: 1)
    {
    }

    /// <summary>Legs done, 0–4.</summary>
    public int Legs { get; private set; }

    /// <summary>Cycles taken off the time by fouls so far.</summary>
    public int PenaltyCycles { get; private set; }

    /// <summary>The cycle the ball crossed the black line, or 0.</summary>
    public int ThroughCycle { get; private set; }

    /// <summary>The cycle leg <paramref name="leg"/> (1–4) was done in, or 0.</summary>
    public int LegCycle(int leg) => _legCycle[leg - 1];

    /// <summary>
    /// Where a fish that touched an obstacle is put back, by legs done (the original's formulas on the
    /// obstacles: the start of the leg it is on), or null after the fourth.
    /// </summary>
    public static (Vector2 Position, float Heading)? FishRestart(int legs)
    {
        var o = PushBallAvoidObstaclesLayout.Obstacles;
        const float L = PushBallAvoidObstaclesLayout.BodyLength;
        const float W = PushBallAvoidObstaclesLayout.BodyWidth;
        return legs switch
        {
            0 => (new Vector2(o[1].Centre.X - o[1].Length - L, o[4].Centre.Y - o[4].Width + W), 0f),
            1 => (new Vector2(o[4].Centre.X + o[4].Length + L, o[4].Centre.Y + o[4].Width + W), 0f),
            2 => (new Vector2(o[9].Centre.X + o[9].Length + L, o[9].Centre.Y + o[9].Width + W), MathF.PI),
            3 => (new Vector2(o[4].Centre.X - o[4].Length - L, o[4].Centre.Y + o[4].Width + W), MathF.PI),
            _ => null,
        };
    }

    /// <summary>Where a ball that touched an obstacle is put back, by legs done, or null after the fourth.</summary>
    public static Vector2? BallRestart(int legs) => legs switch
    {
        < 3 => PushBallAvoidObstaclesLayout.BallStart,
        3 => Vector2.Zero,
        _ => null,
    };

    /// <inheritdoc/>
    protected override bool Score(World world, ReadOnlySpan<ContactRecord> contacts)
    {
        var fish = world.Fish[0];
        var ball = world.Balls[0];
        CountLeg(world.Cycle, fish.Position, ball.Position);
        bool moved = Fouls(world, contacts);
        if (ball.Position.X + ball.Radius <= PushBallAvoidObstaclesLayout.BlackLineX)
        {
            ThroughCycle = world.Cycle;
            AddEvent(new ItemEvent(world.Cycle, "through", 0, -1, 0, double.NaN, "the ball is past the black line"));
            MatchDone = true;
        }
        else if (world.Cycle + PenaltyCycles >= Cycles)
        {
            MatchDone = true;
        }

        return moved;
    }

    /// <inheritdoc/>
    protected override MatchOutcome Decide() => ThroughCycle > 0
        ? new MatchOutcome(0, string.Create(CultureInfo.InvariantCulture, $"ball past the black line in {ThroughCycle / 10.0:0.0} s ({Legs} of 4 legs, {PenaltyCycles / 10.0:0.0} s of penalties)"))
        : new MatchOutcome(-1, string.Create(CultureInfo.InvariantCulture, $"ball not past the black line ({Legs} of 4 legs, {PenaltyCycles / 10.0:0.0} s of penalties)"));

    private void CountLeg(int cycle, Vector2 fish, Vector2 ball)
    {
        var o = PushBallAvoidObstaclesLayout.Obstacles;
        const float L = PushBallAvoidObstaclesLayout.BodyLength;
        const float D = 2f * PushBallAvoidObstaclesLayout.BallRadius;
        bool done = Legs switch
        {
            0 => fish.X > o[0].Centre.X + L,
            1 => fish.X > o[9].Centre.X + L,
            2 => fish.X < o[9].Centre.X - L && ball.X < o[9].Centre.X - D,
            3 => fish.X < o[0].Centre.X - L && ball.X < o[0].Centre.X - D,
            _ => false,
        };
        if (done)
        {
            _legCycle[Legs] = cycle;
            Legs++;
            Scores[0]++;
            AddEvent(cycle, "leg", 0, 0, -1, 1, $"leg {Legs} of 4 done (+1)");
        }
    }

    private bool Fouls(World world, ReadOnlySpan<ContactRecord> contacts)
    {
        if (_quiet)
        {
            _quiet = world.Cycle < _quietSince + QuietCycles;
            return false;
        }

        bool fishFoul = false, ballFoul = false;
        foreach (ref readonly var c in contacts)
        {
            fishFoul |= c.Pair.Kind == PairKind.FishStatic;
            ballFoul |= c.Pair.Kind == PairKind.BallStatic;
        }

        if (!fishFoul && !ballFoul)
        {
            return false;
        }

        _quiet = true;
        _quietSince = world.Cycle;
        if (fishFoul)
        {
            PenaltyCycles += FishFoulCycles;
            AddEvent(new ItemEvent(world.Cycle, "foul", 0, 0, -1, double.NaN, "the fish touches an obstacle: 5 s off the time, back to the start of its leg"));
            if (FishRestart(Legs) is { } restart)
            {
                Placement.Place(world.Fish[0], restart.Position, restart.Heading);
                return true;
            }

            return false;
        }

        PenaltyCycles += BallFoulCycles;
        AddEvent(new ItemEvent(world.Cycle, "foul", 0, -1, 0, double.NaN, "the ball touches an obstacle: 3 s off the time, the ball goes back"));
        if (BallRestart(Legs) is { } place)
        {
            Placement.Place(world.Balls[0], place);
            return true;
        }

        return false;
    }
}
