using System.Globalization;
using static URWPGSim2D.Engine.Items.RelayWithBall.RelayWithBallLayout;

namespace URWPGSim2D.Engine.Items.RelayWithBall;

/// <summary>
/// The rules of 带球接力, as the original's <c>SpeedRelayWithBallIn12Meter</c>. After each cycle, in
/// the original's order:
/// <list type="number">
/// <item>Legs (event <c>leg</c>, +1): legs 1 and 3 end when the ball's centre is in the right pocket
/// (0 &lt; x &lt; 692, |z| &lt; 317), legs 2 and 4 when it is in the left one (−692 &lt; x &lt; 0).</item>
/// <item>Fish fouls (event <c>foul</c>): fish 0 in the bottom channel (|x| &lt; 692, z &gt; 658) is put back
/// at (−1180, 0) facing +x; fish 1 in the top channel (z &lt; −658) at (1180, 0) facing −x.</item>
/// <item>Ball fouls: on legs 2 and 4 the ball in the top channel is put back at (268, −317); on leg 3
/// in the bottom channel at (−268, −317).</item>
/// <item>Four legs done, or the time up, end the match.</item>
/// </list>
/// The score is the number of legs done. <c>HtMissionVariables</c>: <c>FinishedSingleTripCount</c> (0–4).
/// </summary>
internal sealed class RelayWithBallReferee : ItemReferee
{
    private readonly int[] _legCycle = new int[4];

    /// <summary>Creates the referee of one match.</summary>
    public RelayWithBallReferee(RelayWithBallItem item, ScenarioDefinition scenario, int cycles)
        : base(item, scenario, cycles, halves: 1)
    {
    }

    /// <summary>Legs done, 0–4 (the original's <c>FinishedSingleTripCount</c>).</summary>
    public int Legs { get; private set; }

    /// <summary>The cycle leg <paramref name="leg"/> (1–4) was done in, or 0.</summary>
    public int LegCycle(int leg) => _legCycle[leg - 1];

    /// <summary>Where fish <paramref name="fish"/> (0 or 1) is put back after entering the other fish's channel, and its heading.</summary>
    public static (Vector2 Position, float Heading) FishRestart(int fish) => fish == 0
        ? (new Vector2((-FieldLength / 2f) + (2f * BodyLength), 0f), 0f)
        : (new Vector2((FieldLength / 2f) - (2f * BodyLength), 0f), MathF.PI);

    /// <inheritdoc/>
    protected override bool Score(World world, ReadOnlySpan<ContactRecord> contacts)
    {
        var ball = world.Balls[0];
        if (Legs < 4 && InPocket(ball.Position, Legs % 2 == 0 ? 1 : -1))
        {
            _legCycle[Legs] = world.Cycle;
            Legs++;
            Scores[0] = Legs;
            AddEvent(world.Cycle, "leg", 0, -1, 0, 1, $"leg {Legs} of 4 done: the ball is in the {(Legs % 2 == 1 ? "right" : "left")} pocket (+1)");
        }

        bool moved = false;
        for (int k = 0; k < 2 && k < world.Fish.Length; k++)
        {
            var fish = world.Fish[k];
            if (InChannel(fish.Position, top: k == 1))
            {
                var (position, heading) = FishRestart(k);
                Placement.Place(fish, position, heading);
                AddEvent(world.Cycle, "foul", 0, k, -1, double.NaN, $"fish {k} enters the {(k == 1 ? "top" : "bottom")} channel, kept for fish {1 - k}: put back at its end");
                moved = true;
            }
        }

        bool wrongTop = (Legs == 1 || Legs == 3) && InChannel(ball.Position, top: true);
        bool wrongBottom = Legs == 2 && InChannel(ball.Position, top: false);
        if (wrongTop || wrongBottom)
        {
            Placement.Place(ball, new Vector2(wrongTop ? -BallStart.X : BallStart.X, BallStart.Y));
            AddEvent(world.Cycle, "foul", 0, -1, 0, double.NaN, $"the ball enters the {(wrongTop ? "top" : "bottom")} channel on leg {Legs + 1}: put back at the leg's start");
            moved = true;
        }

        MatchDone |= Legs == 4;
        return moved;
    }

    /// <inheritdoc/>
    protected override MatchOutcome Decide()
    {
        string last = Legs > 0 ? string.Create(CultureInfo.InvariantCulture, $", the last in {_legCycle[Legs - 1] / 10.0:0.0} s") : string.Empty;
        return Legs == 4
            ? new MatchOutcome(0, string.Create(CultureInfo.InvariantCulture, $"relay done in {_legCycle[3] / 10.0:0.0} s"))
            : new MatchOutcome(-1, string.Create(CultureInfo.InvariantCulture, $"relay not done ({Legs} of 4 legs{last})"));
    }

    /// <inheritdoc/>
    protected override void UpdateVariables(World world) => Variables.Set("FinishedSingleTripCount", Legs);
}
