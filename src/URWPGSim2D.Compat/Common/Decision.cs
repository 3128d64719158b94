namespace URWPGSim2D.Common;

/// <summary>
/// One fish's command as the original's strategies write it: mutable public fields. The server clamps
/// both to 0..15 (VCode 0 still, 15 fastest; TCode 7 straight, 0 sharpest left, 15 sharpest right).
/// </summary>
[Serializable]
public struct Decision
{
    /// <summary>Speed gear 0..15.</summary>
    public int VCode;

    /// <summary>Turn gear 0..15 (7 = straight).</summary>
    public int TCode;
}
