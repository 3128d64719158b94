using System.Globalization;
using URWPGSim2D.Strategies;

namespace URWPGSim2D.Engine.Items;

/// <summary>
/// An item's state for strategies, the equivalent of the original's <c>Mission.HtMissionVariables</c>:
/// string keys (exactly the original's, e.g. <c>Ball_3_Left_Status</c>, <c>IsYellowFish2Caught</c>,
/// <c>Ball0InHole</c>) and string values (the original's ints as invariant text, which
/// <c>Convert.ToInt32</c> reads). Keys keep the order they were added in (the SDK's ordered table).
/// Refreshed by the referee after every cycle; setting a small integer, or the value a key already has, allocates nothing.
/// </summary>
public sealed class MissionVariables : OrderedVariables
{
    private static readonly string[] Small = CreateSmall();

    /// <summary>Sets a key to an integer, written in invariant culture (a value the key already has is not written again).</summary>
    public void Set(string key, int value)
    {
        if (value >= 0 && value < Small.Length)
        {
            Set(key, Small[value]);
        }
        else if (!(TryGetValue(key, out string? now) && int.TryParse(now, NumberStyles.AllowLeadingSign, CultureInfo.InvariantCulture, out int was) && was == value))
        {
            Set(key, value.ToString(CultureInfo.InvariantCulture));
        }
    }

    /// <summary>The value of a key as an integer (what a strategy's <c>Convert.ToInt32</c> gives).</summary>
    public int GetInt32(string key) => int.Parse(this[key], NumberStyles.AllowLeadingSign, CultureInfo.InvariantCulture);

    private static string[] CreateSmall()
    {
        var s = new string[64];
        for (int i = 0; i < s.Length; i++)
        {
            s[i] = i.ToString(CultureInfo.InvariantCulture);
        }

        return s;
    }
}
