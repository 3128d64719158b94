using System;
using System.Collections.Generic;
using System.Drawing;
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

    /// <summary>A copy of size, direction, border and centre.</summary>
    /// <returns>A new <see cref="RectangularDynamic"/>.</returns>
    public virtual object Clone() => new RectangularDynamic
    {
        BorderWidthPix = BorderWidthPix, WidthMm = WidthMm, LengthMm = LengthMm,
        LengthDirectionRad = LengthDirectionRad, DirectionRad = DirectionRad, PositionMm = PositionMm,
    };
}
