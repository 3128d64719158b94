using Xna = Microsoft.Xna.Framework;

namespace URWPGSim2D.Common;

/// <summary>A rectangular static obstacle.</summary>
[Serializable]
public class RectangularObstacle : RectangularStatic
{
    /// <summary>Creates an unnamed 100 × 100 mm obstacle.</summary>
    public RectangularObstacle()
    {
    }

    /// <summary>Creates a named obstacle.</summary>
    /// <param name="strName">Name.</param>
    /// <param name="positionMm">Centre, mm.</param>
    /// <param name="color">Border and fill colour.</param>
    /// <param name="lengthMm">Length, mm.</param>
    /// <param name="widthMm">Width, mm.</param>
    /// <param name="directionDeg">Direction, degrees.</param>
    public RectangularObstacle(string strName, Xna.Vector3 positionMm, Color color, int lengthMm, int widthMm, float directionDeg)
        : this(strName, positionMm, color, color, 0, lengthMm, widthMm, directionDeg)
    {
    }

    /// <summary>Creates a named obstacle.</summary>
    /// <param name="strName">Name.</param>
    /// <param name="positionMm">Centre, mm.</param>
    /// <param name="colorBorder">Border colour.</param>
    /// <param name="colorFilled">Fill colour.</param>
    /// <param name="lengthMm">Length, mm.</param>
    /// <param name="widthMm">Width, mm.</param>
    /// <param name="directionDeg">Direction, degrees.</param>
    public RectangularObstacle(string strName, Xna.Vector3 positionMm, Color colorBorder, Color colorFilled, int lengthMm, int widthMm, float directionDeg)
        : this(strName, positionMm, colorBorder, colorFilled, 0, lengthMm, widthMm, directionDeg)
    {
    }

    /// <summary>Creates a named obstacle.</summary>
    /// <param name="strName">Name.</param>
    /// <param name="positionMm">Centre, mm.</param>
    /// <param name="colorBorder">Border colour.</param>
    /// <param name="colorFilled">Fill colour.</param>
    /// <param name="borderWithPix">Border width, px.</param>
    /// <param name="lengthMm">Length, mm.</param>
    /// <param name="widthMm">Width, mm.</param>
    /// <param name="directionDeg">Direction, degrees.</param>
    public RectangularObstacle(string strName, Xna.Vector3 positionMm, Color colorBorder, Color colorFilled, int borderWithPix, int lengthMm, int widthMm, float directionDeg)
        : base(positionMm, colorBorder, colorFilled, borderWithPix, lengthMm, widthMm, directionDeg)
    {
        Name = strName;
        IsDeletionAllowed = true;
        CalculateCollisionDetectionParas();
    }

    /// <summary>Name.</summary>
    public string Name = string.Empty;

    /// <summary>Whether the original's user interface may delete it.</summary>
    public bool IsDeletionAllowed;

    /// <inheritdoc/>
    public override object Clone()
    {
        var copy = new RectangularObstacle { Name = Name };
        CopyTo(copy);
        return copy;
    }
}
