using URWPGSim2D.Engine.Simulation.Kinematics;

namespace URWPGSim2D.Engine.Items.Demo;

/// <summary>
/// The turn code that brings a fish's turn rate to a wanted one quickly. The rate approaches its
/// gear's table value by a tenth of the gap per cycle (a one-second lag), so the code asks for more
/// than wanted while the rate is far from it (overdrive), and the nearest table value once it is close.
/// </summary>
internal static class TurnCode
{
    /// <summary>How much of the remaining gap the code asks for beyond the wanted rate.</summary>
    public const float Overdrive = 2f;

    /// <summary>The TCode for a wanted turn rate <paramref name="wanted"/> given the current one (rad/s).</summary>
    public static int For(float wanted, float current) => Nearest(wanted + (Overdrive * (wanted - current)));

    /// <summary>The TCode whose table rate is nearest to <paramref name="rate"/>.</summary>
    public static int Nearest(float rate)
    {
        var table = TurnTable.Rates;
        int best = TurnTable.Straight;
        float bestGap = float.PositiveInfinity;
        for (int code = 0; code < table.Length; code++)
        {
            float gap = MathF.Abs(table[code] - rate);
            if (gap < bestGap)
            {
                best = code;
                bestGap = gap;
            }
        }

        return best;
    }
}
