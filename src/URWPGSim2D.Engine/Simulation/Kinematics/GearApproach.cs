namespace URWPGSim2D.Engine.Simulation.Kinematics;

/// <summary>
/// The original's per-cycle approach of a speed (or angular speed) to its gear's table value, an
/// exponential approach by a tenth of the remaining gap. State: the value v, the current code c and
/// the last target code p; each cycle, with the decision's target code d and table T:
/// <list type="number">
/// <item>if d ≠ p and d = c: c ← p (a reversal before the last change was reached);</item>
/// <item>if c = p = d and |v − T[c]| &gt; 0.01: c ← the code nearest to v (<see cref="NearestCode"/>);</item>
/// <item>if d ≠ c: v ← v + (T[d] − v)/10, and c ← d once |T[d] − v| ≤ |T[d] − T[c]|/10;</item>
/// <item>p ← d.</item>
/// </list>
/// From rest toward 307 mm/s: 30.7, 58.3, 83.2, … (v_k = 307·(1 − 0.9^k)). The value is never
/// snapped onto the table, so it can settle a few units off it (303.6 mm/s for VCode 14; about
/// 3.2 mm/s for VCode 0 after a run at speed).
/// </summary>
public struct GearApproach
{
    /// <summary>Differences up to this size count as "at the table value" (rule 2).</summary>
    public const float Tolerance = 0.01f;

    /// <summary>The current value v (mm/s or rad/s).</summary>
    public float Value;

    /// <summary>The current code c.</summary>
    public int Code;

    /// <summary>The last target code p.</summary>
    public int LastTarget;

    /// <summary>Takes one cycle's step toward the table value of <paramref name="target"/>.</summary>
    /// <param name="target">The decision's code d (clamped into the table).</param>
    /// <param name="table">The gear table T (speeds or angular speeds by code).</param>
    public void Advance(int target, ReadOnlySpan<float> table)
    {
        int d = Math.Clamp(target, 0, table.Length - 1);
        int c = Math.Clamp(Code, 0, table.Length - 1);
        int p = Math.Clamp(LastTarget, 0, table.Length - 1);
        if (d != p && d == c)
        {
            c = p;
        }

        if (c == p && p == d && MathF.Abs(Value - table[c]) > Tolerance)
        {
            c = NearestCode(Value, table);
        }

        if (d != c)
        {
            Value += (table[d] - Value) / 10f;
            if (MathF.Abs(table[d] - Value) <= MathF.Abs(table[d] - table[c]) / 10f)
            {
                c = d;
            }
        }

        Code = c;
        LastTarget = d;
    }

    /// <summary>Sets the value directly and the codes to the nearest one (the initial state).</summary>
    /// <param name="value">The new value.</param>
    /// <param name="table">The gear table the value belongs to.</param>
    public void Reset(float value, ReadOnlySpan<float> table)
    {
        Value = value;
        Code = NearestCode(value, table);
        LastTarget = Code;
    }

    /// <summary>
    /// The code whose table value is nearest to <paramref name="value"/> as the original decides it:
    /// the first code i whose midpoint (T[i] + T[i+1])/2 with the next entry lies above the value
    /// (so below T[0] gives 0 and above the last midpoint the last code). The speed table is not
    /// monotone (298, 294 at VCodes 12, 13); the midpoints still decide, in table order.
    /// </summary>
    /// <param name="value">The value to convert.</param>
    /// <param name="table">The gear table.</param>
    public static int NearestCode(float value, ReadOnlySpan<float> table)
    {
        for (int i = 0; i < table.Length - 1; i++)
        {
            if (value < 0.5f * (table[i] + table[i + 1]))
            {
                return i;
            }
        }

        return table.Length - 1;
    }
}
