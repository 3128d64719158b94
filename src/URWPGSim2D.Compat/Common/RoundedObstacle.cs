using Xna = Microsoft.Xna.Framework;

namespace URWPGSim2D.Common;

/// <summary>A round static obstacle.</summary>
[Serializable]
public class RoundedObstacle : RoundedStatic
{
    /// <summary>Creates an unnamed obstacle of radius 58 mm.</summary>
    public RoundedObstacle()
    {
    }

    /// <summary>Creates a named obstacle.</summary>
    /// <param name="strName">Name.</param>
    /// <param name="positionMm">Centre, mm.</param>
    /// <param name="color">Border and fill colour.</param>
    /// <param name="radiusMm">Radius, mm.</param>
    public RoundedObstacle(string strName, Xna.Vector3 positionMm, Color color, int radiusMm)
        : this(strName, positionMm, color, color, 0, radiusMm)
    {
    }

    /// <summary>Creates a named obstacle.</summary>
    /// <param name="strName">Name.</param>
    /// <param name="positionMm">Centre, mm.</param>
    /// <param name="colorBorder">Border colour.</param>
    /// <param name="colorFilled">Fill colour.</param>
    /// <param name="radiusMm">Radius, mm.</param>
    public RoundedObstacle(string strName, Xna.Vector3 positionMm, Color colorBorder, Color colorFilled, int radiusMm)
        : this(strName, positionMm, colorBorder, colorFilled, 0, radiusMm)
    {
    }

    /// <summary>Creates a named obstacle.</summary>
    /// <param name="strName">Name.</param>
    /// <param name="positionMm">Centre, mm.</param>
    /// <param name="colorBorder">Border colour.</param>
    /// <param name="colorFilled">Fill colour.</param>
    /// <param name="borderWithPix">Border width, px.</param>
    /// <param name="radiusMm">Radius, mm.</param>
    public RoundedObstacle(string strName, Xna.Vector3 positionMm, Color colorBorder, Color colorFilled, int borderWithPix, int radiusMm)
        : base(positionMm, colorBorder, colorFilled, borderWithPix, radiusMm)
    {
        Name = strName;
        IsDeletionAllowed = true;
    }

    /// <summary>Name.</summary>
    public string Name = string.Empty;

    /// <summary>Whether the original's user interface may delete it.</summary>
    public bool IsDeletionAllowed;

    /// <inheritdoc/>
    public override object Clone()
    {
        var copy = new RoundedObstacle { Name = Name };
        CopyTo(copy);
        return copy;
    }
}
