using Xna = Microsoft.Xna.Framework;

namespace URWPGSim2D.Common;

/// <summary>A channel (a rectangle fish swim through); no item here uses one.</summary>
[Serializable]
public class Channel : RectangularStatic
{
    /// <summary>Creates an unnamed channel.</summary>
    public Channel()
    {
    }

    /// <summary>Creates a named channel.</summary>
    /// <param name="strName">Name.</param>
    /// <param name="positionMm">Centre, mm.</param>
    /// <param name="color">Border and fill colour.</param>
    /// <param name="lengthMm">Length, mm.</param>
    /// <param name="widthMm">Width, mm.</param>
    /// <param name="directionDeg">Direction, degrees.</param>
    public Channel(string strName, Xna.Vector3 positionMm, Color color, int lengthMm, int widthMm, float directionDeg)
        : this(strName, positionMm, color, color, 0, lengthMm, widthMm, directionDeg)
    {
    }

    /// <summary>Creates a named channel with separate border and fill colours.</summary>
    /// <param name="strName">Name.</param>
    /// <param name="positionMm">Centre, mm.</param>
    /// <param name="colorBorder">Border colour.</param>
    /// <param name="colorFilled">Fill colour.</param>
    /// <param name="lengthMm">Length, mm.</param>
    /// <param name="widthMm">Width, mm.</param>
    /// <param name="directionDeg">Direction, degrees.</param>
    public Channel(string strName, Xna.Vector3 positionMm, Color colorBorder, Color colorFilled, int lengthMm, int widthMm, float directionDeg)
        : this(strName, positionMm, colorBorder, colorFilled, 0, lengthMm, widthMm, directionDeg)
    {
    }

    /// <summary>Creates a named channel with separate border and fill colours and a border width.</summary>
    /// <param name="strName">Name.</param>
    /// <param name="positionMm">Centre, mm.</param>
    /// <param name="colorBorder">Border colour.</param>
    /// <param name="colorFilled">Fill colour.</param>
    /// <param name="borderWithPix">Border width, px.</param>
    /// <param name="lengthMm">Length, mm.</param>
    /// <param name="widthMm">Width, mm.</param>
    /// <param name="directionDeg">Direction, degrees.</param>
    public Channel(string strName, Xna.Vector3 positionMm, Color colorBorder, Color colorFilled, int borderWithPix, int lengthMm, int widthMm, float directionDeg)
        : base(positionMm, colorBorder, colorFilled, borderWithPix, lengthMm, widthMm, directionDeg)
    {
        Name = strName;
    }

    /// <summary>Name.</summary>
    public string Name = string.Empty;

    /// <inheritdoc/>
    public override object Clone()
    {
        var copy = new Channel { Name = Name };
        CopyTo(copy);
        return copy;
    }
}
