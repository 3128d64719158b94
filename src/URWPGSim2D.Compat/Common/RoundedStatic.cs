using Xna = Microsoft.Xna.Framework;

namespace URWPGSim2D.Common;

/// <summary>Base of round static objects: radius and centre.</summary>
[Serializable]
public class RoundedStatic : ICloneable
{
    /// <summary>Creates a round object of radius 58 mm.</summary>
    public RoundedStatic()
    {
        SetRoundedStatic();
    }

    /// <summary>The constructors of the named kinds: a round object of the given centre, colours, border and radius.</summary>
    private protected RoundedStatic(Xna.Vector3 positionMm, Color colorBorder, Color colorFilled, int borderWidthPix, int radiusMm)
    {
        PositionMm = positionMm;
        ColorBorder = colorBorder;
        ColorFilled = colorFilled;
        BorderWidthPix = borderWidthPix;
        RadiusMm = radiusMm;
    }

    /// <summary>Radius, mm.</summary>
    public int RadiusMm;

    /// <summary>Fill colour (display only).</summary>
    public Color ColorFilled;

    /// <summary>Border colour (display only).</summary>
    public Color ColorBorder;

    /// <summary>Border width, px (display only).</summary>
    public int BorderWidthPix;

    /// <summary>Centre, mm (Y = 0).</summary>
    public Xna.Vector3 PositionMm;

    /// <summary>Sets the default radius (58 mm) and border.</summary>
    public void SetRoundedStatic()
    {
        RadiusMm = 58;
        BorderWidthPix = 0;
    }

    /// <summary>A copy of radius, border and centre.</summary>
    /// <returns>A new object of the same kind.</returns>
    public virtual object Clone()
    {
        var copy = new RoundedStatic();
        CopyTo(copy);
        return copy;
    }

    /// <summary>Copies radius, border and centre onto <paramref name="target"/>.</summary>
    /// <param name="target">The object to overwrite.</param>
    public void CopyTo(RoundedStatic target)
    {
        ArgumentNullException.ThrowIfNull(target);
        target.RadiusMm = RadiusMm;
        target.BorderWidthPix = BorderWidthPix;
        target.PositionMm = PositionMm;
    }
}
