using Xna = Microsoft.Xna.Framework;

namespace URWPGSim2D.Common;

/// <summary>A moving rectangular obstacle of the original (no item here has one; the list stays empty).</summary>
[Serializable]
public class RectangularDynamic : ICloneable
{
    /// <summary>Creates a 100 × 100 mm rectangle at the origin.</summary>
    public RectangularDynamic()
    {
        for (int i = 0; i < 4; i++)
        {
            PolygonVertices.Add(default);
        }
    }

    /// <summary>
    /// Creates a named moving rectangle (the original's constructor, which also allows deletion and starts the cycle
    /// counter <see cref="TimesCouter"/> at <paramref name="circleTimes"/>). Unlike the original's, it also makes the four
    /// corner entries, so <see cref="CalculateCollisionDetectionParas"/> can be called on it.
    /// </summary>
    /// <param name="strName">Name.</param>
    /// <param name="positionMm">Centre, mm.</param>
    /// <param name="colorBorder">Border colour.</param>
    /// <param name="colorFilled">Fill colour.</param>
    /// <param name="borderWithPix">Border width, px.</param>
    /// <param name="lengthMm">Length, mm.</param>
    /// <param name="widthMm">Width, mm.</param>
    /// <param name="directionDeg">Direction of the length, degrees.</param>
    /// <param name="velocityMmPs">Speed, mm/s.</param>
    /// <param name="velocityDirectionRad">Direction of motion, rad.</param>
    /// <param name="angularVelocityRadPs">Angular speed, rad/s.</param>
    /// <param name="circleTimes">Cycles in one back-and-forth loop.</param>
    public RectangularDynamic(string strName, Xna.Vector3 positionMm, Color colorBorder, Color colorFilled, int borderWithPix, int lengthMm, int widthMm,
        float directionDeg, float velocityMmPs, float velocityDirectionRad, float angularVelocityRadPs, int circleTimes)
        : this()
    {
        Name = strName;
        PositionMm = positionMm;
        ColorBorder = colorBorder;
        ColorFilled = colorFilled;
        BorderWidthPix = borderWithPix;
        LengthMm = lengthMm;
        WidthMm = widthMm;
        DirectionRad = Xna.MathHelper.ToRadians(directionDeg);
        IsDeletionAllowed = true;
        VelocityMmPs = velocityMmPs;
        VelocityDirectionRad = velocityDirectionRad;
        AngularVelocityRadPs = angularVelocityRadPs;
        CircleTimes = circleTimes;
        TimesCouter = circleTimes;
    }

    /// <summary>Name.</summary>
    public string Name = string.Empty;

    /// <summary>Whether the original's user interface may delete it.</summary>
    public bool IsDeletionAllowed;

    /// <summary>Length along <see cref="DirectionRad"/>, mm.</summary>
    public int LengthMm = 100;

    /// <summary>Width, mm.</summary>
    public int WidthMm = 100;

    /// <summary>Direction, rad.</summary>
    public float DirectionRad;

    /// <summary>Fill colour (display only).</summary>
    public Color ColorFilled;

    /// <summary>Border colour (display only).</summary>
    public Color ColorBorder;

    /// <summary>Border width, px (display only).</summary>
    public int BorderWidthPix;

    /// <summary>Centre, mm.</summary>
    public Xna.Vector3 PositionMm;

    /// <summary>Last cycle's centre.</summary>
    public Xna.Vector3 PrePositionMm;

    /// <summary>Direction of the length, rad.</summary>
    public float LengthDirectionRad;

    /// <summary>Last cycle's length direction.</summary>
    public float PreLengthDirectionRad;

    /// <summary>Speed, mm/s.</summary>
    public float VelocityMmPs;

    /// <summary>Last cycle's speed.</summary>
    public float PreVelocityMmPs;

    /// <summary>Direction of motion, rad.</summary>
    public float VelocityDirectionRad;

    /// <summary>Last cycle's direction of motion.</summary>
    public float PreVelocityDirectionRad;

    /// <summary>Angular speed, rad/s.</summary>
    public float AngularVelocityRadPs;

    /// <summary>Last cycle's angular speed.</summary>
    public float PreAngularVelocityRadPs;

    /// <summary>Cycles of one back-and-forth.</summary>
    public int CircleTimes;

    /// <summary>Cycle counter of the back-and-forth.</summary>
    public int TimesCouter;

    /// <summary>This cycle's contact.</summary>
    public CollisionType Collision;

    /// <summary>Last cycle's contact.</summary>
    public CollisionType PreCollision;

    /// <summary>Circumcircle radius, mm.</summary>
    public int CircumcircleRadiusMm;

    /// <summary>Corners, mm (zeros in a strategy's copy).</summary>
    public List<Xna.Vector3> PolygonVertices = new(4);

    /// <summary>Sets the original's defaults: 100 × 100 mm, direction 0, no border.</summary>
    public void SetRectangularDynamic()
    {
        LengthMm = 100;
        WidthMm = 100;
        DirectionRad = 0f;
        BorderWidthPix = 0;
    }

    /// <summary>
    /// Computes <see cref="CircumcircleRadiusMm"/> (whole mm) and the four corners <see cref="PolygonVertices"/> from the
    /// centre, length, width and <see cref="DirectionRad"/>, as <see cref="RectangularStatic.CalculateCollisionDetectionParas"/> does.
    /// </summary>
    public void CalculateCollisionDetectionParas()
    {
        CircumcircleRadiusMm = RectangularStatic.Corners(PolygonVertices, PositionMm, LengthMm, WidthMm, DirectionRad);
    }

    /// <summary>A copy of size, direction, border and centre.</summary>
    /// <returns>A new <see cref="RectangularDynamic"/>.</returns>
    public virtual object Clone() => new RectangularDynamic
    {
        BorderWidthPix = BorderWidthPix, WidthMm = WidthMm, LengthMm = LengthMm,
        LengthDirectionRad = LengthDirectionRad, DirectionRad = DirectionRad, PositionMm = PositionMm,
    };
}
