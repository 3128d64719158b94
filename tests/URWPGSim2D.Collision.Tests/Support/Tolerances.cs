namespace URWPGSim2D.Collision.Tests.Support;

/// <summary>The accuracy the narrow phase promises, in mm, in one place.</summary>
public static class Tolerances
{
    /// <summary>The goal: penetration depth within 0.01 mm of the truth (float32, ±25,000 mm, sizes 5–1,600 mm).</summary>
    public const double Depth = 0.01;

    /// <summary>
    /// Around touching (|true depth| below this) either answer is accepted: float32 cannot place a
    /// coordinate near 25,000 mm closer than 0.002 mm, and 8-DOP diagonal slabs (near 35,000 mm)
    /// are stored to 0.004 mm.
    /// </summary>
    public const double TouchingBand = 0.005;

    /// <summary>How far outside either shape an action point may lie (float32 output near 25,000 mm).</summary>
    public const double ActionPoint = 0.01;

    /// <summary>How far apart the action points of two equivalent queries (swapped, translated) may lie.</summary>
    public const double SameActionPoint = 0.01;

    /// <summary>How far from 1 a unit normal's length may be.</summary>
    public const double UnitLength = 1e-5;
}
