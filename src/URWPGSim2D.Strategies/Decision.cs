namespace URWPGSim2D.Strategies;

/// <summary>
/// One fish's command for the next cycle: a speed gear and a turn gear, each 0..15
/// (TCode 7 swims straight, lower turns left, higher turns right).
/// </summary>
public readonly struct Decision : IEquatable<Decision>
{
    /// <summary>Creates a decision; the codes are clamped to 0..15.</summary>
    /// <param name="vcode">Speed gear 0..15.</param>
    /// <param name="tcode">Turn gear 0..15.</param>
    public Decision(int vcode, int tcode)
    {
        VCode = Math.Clamp(vcode, 0, 15);
        TCode = Math.Clamp(tcode, 0, 15);
    }

    /// <summary>Speed gear 0..15.</summary>
    public int VCode { get; }

    /// <summary>Turn gear 0..15 (7 = straight).</summary>
    public int TCode { get; }

    /// <summary>Stand still, straight: VCode 0, TCode 7.</summary>
    public static Decision Stop => new(0, 7);

    /// <inheritdoc/>
    public bool Equals(Decision other) => VCode == other.VCode && TCode == other.TCode;

    /// <inheritdoc/>
    public override bool Equals(object? obj) => obj is Decision other && Equals(other);

    /// <inheritdoc/>
    public override int GetHashCode() => (VCode * 16) + TCode;

    /// <summary>Equality of both codes.</summary>
    /// <param name="left">First decision.</param>
    /// <param name="right">Second decision.</param>
    public static bool operator ==(Decision left, Decision right) => left.Equals(right);

    /// <summary>Inequality of either code.</summary>
    /// <param name="left">First decision.</param>
    /// <param name="right">Second decision.</param>
    public static bool operator !=(Decision left, Decision right) => !left.Equals(right);

    /// <inheritdoc/>
    public override string ToString() => $"V{VCode} T{TCode}";
}
