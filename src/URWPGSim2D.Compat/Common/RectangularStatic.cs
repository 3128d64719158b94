using Xna = Microsoft.Xna.Framework;

namespace URWPGSim2D.Common;

/// <summary>Base of rectangular static objects: centre, length along the direction, width across it.</summary>
[Serializable]
public class RectangularStatic : ICloneable
{
    /// <summary>Creates a 100 × 100 mm rectangle at the origin.</summary>
    public RectangularStatic()
    {
        SetRectangularStatic();
    }

    /// <summary>The constructors of the named kinds: a rectangle of the given centre, colours, border, size and direction.</summary>
    private protected RectangularStatic(Xna.Vector3 positionMm, Color colorBorder, Color colorFilled, int borderWidthPix, int lengthMm, int widthMm, float directionDeg)
        : this()
    {
        PositionMm = positionMm;
        ColorBorder = colorBorder;
        ColorFilled = colorFilled;
        BorderWidthPix = borderWidthPix;
        LengthMm = lengthMm;
        WidthMm = widthMm;
        DirectionRad = Xna.MathHelper.ToRadians(directionDeg);
    }

    /// <summary>Length along <see cref="DirectionRad"/>, mm.</summary>
    public int LengthMm;

    /// <summary>Width across the direction, mm.</summary>
    public int WidthMm;

    /// <summary>Direction of the length, rad from +X toward +Z.</summary>
    public float DirectionRad;

    /// <summary>Fill colour (display only).</summary>
    public Color ColorFilled;

    /// <summary>Border colour (display only).</summary>
    public Color ColorBorder;

    /// <summary>Border width, px (display only).</summary>
    public int BorderWidthPix;

    /// <summary>Centre, mm (Y = 0).</summary>
    public Xna.Vector3 PositionMm;

    /// <summary>The original's second direction field (copied as is).</summary>
    public float LengthDirectionRad;

    /// <summary>Circumcircle radius, mm.</summary>
    public int CircumcircleRadiusMm;

    /// <summary>Corners (top-left, top-right, bottom-right, bottom-left at direction 0), mm. Not copied to strategies: zeros.</summary>
    public List<Xna.Vector3> PolygonVertices = new(4);

    /// <summary>Sets the default 100 × 100 mm size and four zero corners.</summary>
    public void SetRectangularStatic()
    {
        LengthMm = 100;
        WidthMm = 100;
        DirectionRad = 0f;
        BorderWidthPix = 0;
        PolygonVertices.Clear();
        for (int i = 0; i < 4; i++)
        {
            PolygonVertices.Add(default);
        }
    }

    /// <summary>Computes <see cref="CircumcircleRadiusMm"/> and the corners from centre, size and direction.</summary>
    public void CalculateCollisionDetectionParas()
    {
        CircumcircleRadiusMm = Corners(PolygonVertices, PositionMm, LengthMm, WidthMm, DirectionRad);
    }

    /// <summary>A copy of size, direction, border and centre (not the corners).</summary>
    /// <returns>A new object of the same kind.</returns>
    public virtual object Clone()
    {
        var copy = new RectangularStatic();
        CopyTo(copy);
        return copy;
    }

    /// <summary>Copies size, direction, border and centre onto <paramref name="target"/>.</summary>
    /// <param name="target">The object to overwrite.</param>
    public void CopyTo(RectangularStatic target)
    {
        ArgumentNullException.ThrowIfNull(target);
        target.BorderWidthPix = BorderWidthPix;
        target.WidthMm = WidthMm;
        target.LengthMm = LengthMm;
        target.LengthDirectionRad = LengthDirectionRad;
        target.DirectionRad = DirectionRad;
        target.PositionMm = PositionMm;
    }

    /// <summary>
    /// Writes the four corners of a rectangle (top-left, top-right, bottom-right, bottom-left at direction 0) into
    /// <paramref name="corners"/> and returns its circumcircle radius in whole mm: what
    /// <see cref="CalculateCollisionDetectionParas"/> and <see cref="RectangularDynamic.CalculateCollisionDetectionParas"/> compute.
    /// </summary>
    internal static int Corners(List<Xna.Vector3> corners, Xna.Vector3 centre, int lengthMm, int widthMm, float directionRad)
    {
        float sin = MathF.Sin(directionRad), cos = MathF.Cos(directionRad);
        float hl = lengthMm / 2f, hw = widthMm / 2f;
        float x = centre.X, z = centre.Z;
        corners[0] = new(x - (hl * cos) + (hw * sin), 0f, z - (hl * sin) - (hw * cos));
        corners[1] = new(x + (hl * cos) + (hw * sin), 0f, z + (hl * sin) - (hw * cos));
        corners[2] = new(x + (hl * cos) - (hw * sin), 0f, z + (hl * sin) + (hw * cos));
        corners[3] = new(x - (hl * cos) - (hw * sin), 0f, z - (hl * sin) + (hw * cos));
        return (int)Math.Sqrt((lengthMm * lengthMm) + (widthMm * widthMm)) / 2;
    }
}
