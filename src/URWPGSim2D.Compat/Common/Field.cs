using Xna = Microsoft.Xna.Framework;

namespace URWPGSim2D.Common;

/// <summary>
/// The field: sizes in mm (origin at the centre, +X right, +Z down) and the original's display sizes
/// in pixels. One instance per process (<see cref="Instance"/>), as in the original; the server sets it
/// to the match's field before calling strategies.
/// </summary>
[Serializable]
public class Field : ICloneable
{
    private static readonly Field Shared = new();

    private Field()
    {
        for (int i = 0; i < 4; i++)
        {
            BorderLeftTopVertices.Add(default);
            BorderLeftBottomVertices.Add(default);
            BorderRightTopVertices.Add(default);
            BorderRightBottomVertices.Add(default);
        }

        SetField();
    }

    /// <summary>How a goal block's hook is oriented in the original's drawing.</summary>
    public enum GoalBlockType
    {
        /// <summary>Hook inside counter-clockwise.</summary>
        TYPE11 = 0,

        /// <summary>Hook inside clockwise.</summary>
        TYPE12,
    }

    /// <summary>The field of this process.</summary>
    /// <returns>The one <see cref="Field"/>.</returns>
    public static Field Instance() => Shared;

    /// <summary>Millimetres per pixel of the original's display.</summary>
    public double ScaleMmToPix { get; set; }

    /// <summary>Millimetres per pixel along X.</summary>
    public double ScaleMmToPixX { get; set; }

    /// <summary>Millimetres per pixel along Z.</summary>
    public double ScaleMmToPixZ { get; set; }

    /// <summary>X pixel of the field centre in the original's display.</summary>
    public int FieldCenterXPix { get; set; }

    /// <summary>Z pixel of the field centre in the original's display.</summary>
    public int FieldCenterZPix { get; set; }

    /// <summary>Width of the original's side panel, px (312).</summary>
    public int TabControlLengthXPix { get; set; }

    /// <summary>Height of the original's side panel, px (550).</summary>
    public int TabControlLengthZPix { get; set; }

    /// <summary>Inner border of the drawn field, px (5).</summary>
    public int FieldInnerBorderPix { get; set; }

    /// <summary>Outer border of the drawn field, px (20).</summary>
    public int FieldOuterBorderPix { get; set; }

    /// <summary>Gap between field and side panel, px (10).</summary>
    public int SpanBetweenFieldAndTabControlPix { get; set; }

    /// <summary>Window padding, px (10).</summary>
    public int FormPaddingPix { get; set; }

    /// <summary>Width of the drawing area, px.</summary>
    public int PictureBoxXPix { get; set; }

    /// <summary>Height of the drawing area, px.</summary>
    public int PictureBoxZPix { get; set; }

    /// <summary>Window width, px.</summary>
    public int FormLengthXPix { get; set; }

    /// <summary>Window height, px.</summary>
    public int FormLengthZPix { get; set; }

    /// <summary>Field length, px.</summary>
    public int FieldLengthXPix { get; set; }

    /// <summary>Field width, px.</summary>
    public int FieldLengthZPix { get; set; }

    /// <summary>Goal width, px.</summary>
    public int GoalWidthPix { get; set; }

    /// <summary>Goal depth, px.</summary>
    public int GoalDepthPix { get; set; }

    /// <summary>Goal block width, px.</summary>
    public int GoalBlockWidthPix { get; set; }

    /// <summary>Goal block depth, px.</summary>
    public int GoalBlockDepthPix { get; set; }

    /// <summary>Forbidden zone extent along Z, px.</summary>
    public int ForbiddenZoneLengthZPix { get; set; }

    /// <summary>Forbidden zone extent along X, px.</summary>
    public int ForbiddenZoneLengthXPix { get; set; }

    /// <summary>Centre circle radius, px.</summary>
    public int CenterCircleRadiusPix { get; set; }

    /// <summary>Transport target circle radius, px.</summary>
    public int MovingCircleRadiusPix { get; set; }

    /// <summary>Transport offset along Z, px.</summary>
    public int OffsetHeightPix { get; set; }

    /// <summary>Transport offset along X, px.</summary>
    public int OffsetWidthPix { get; set; }

    /// <summary>Field length along X, mm (3000; 4500 for large items).</summary>
    public int FieldLengthXMm { get; set; }

    /// <summary>Field width along Z, mm (2000; 3000 for large items).</summary>
    public int FieldLengthZMm { get; set; }

    /// <summary>Configured field length, mm.</summary>
    public int FieldLengthXOriMm { get; set; }

    /// <summary>Configured field width, mm.</summary>
    public int FieldLengthZOriMm { get; set; }

    /// <summary>Goal mouth width along Z, mm (400).</summary>
    public int GoalWidthMm { get; set; }

    /// <summary>Goal depth along X, mm (150).</summary>
    public int GoalDepthMm { get; set; }

    /// <summary>Forbidden zone extent along Z, mm (1000).</summary>
    public int ForbiddenZoneLengthZMm { get; set; }

    /// <summary>Forbidden zone extent along X, mm (400).</summary>
    public int ForbiddenZoneLengthXMm { get; set; }

    /// <summary>Centre circle radius, mm (200).</summary>
    public int CenterCircleRadiusMm { get; set; }

    /// <summary>Transport offset along Z, mm (1200).</summary>
    public int OffsetHeightMm { get; set; }

    /// <summary>Transport offset along X, mm (1900).</summary>
    public int OffsetWidthMm { get; set; }

    /// <summary>Transport target circle radius, mm (80).</summary>
    public int MovingCircleRadiusMm { get; set; }

    /// <summary>X of the left edge, mm (−length/2).</summary>
    public int LeftMm { get; set; }

    /// <summary>Z of the top edge, mm (−width/2).</summary>
    public int TopMm { get; set; }

    /// <summary>X of the right edge, mm (length/2).</summary>
    public int RightMm { get; set; }

    /// <summary>Z of the bottom edge, mm (width/2).</summary>
    public int BottomMm { get; set; }

    /// <summary>Corners of the top-left goal block, mm.</summary>
    public List<Xna.Vector3> BorderLeftTopVertices = new(4);

    /// <summary>Corners of the bottom-left goal block, mm.</summary>
    public List<Xna.Vector3> BorderLeftBottomVertices = new(4);

    /// <summary>Corners of the top-right goal block, mm.</summary>
    public List<Xna.Vector3> BorderRightTopVertices = new(4);

    /// <summary>Corners of the bottom-right goal block, mm.</summary>
    public List<Xna.Vector3> BorderRightBottomVertices = new(4);

    /// <summary>Whether the goal blocks sit regularly in the four corners.</summary>
    public bool IsGoalBlockRegular = true;

    /// <summary>Sets the standard 3000 × 2000 field and everything derived from it.</summary>
    public void SetField()
    {
        TabControlLengthXPix = 312;
        TabControlLengthZPix = 550;
        FieldInnerBorderPix = 5;
        FieldOuterBorderPix = 20;
        SpanBetweenFieldAndTabControlPix = 10;
        FormPaddingPix = 10;
        FieldLengthXMm = 3000;
        FieldLengthZMm = 2000;
        GoalDepthMm = 150;
        GoalWidthMm = 400;
        MovingCircleRadiusMm = 80;
        ForbiddenZoneLengthXMm = 400;
        ForbiddenZoneLengthZMm = 1000;
        CenterCircleRadiusMm = 200;
        OffsetHeightMm = 1200;
        OffsetWidthMm = 1900;
        FieldLengthXOriMm = FieldLengthXMm;
        FieldLengthZOriMm = FieldLengthZMm;
        FieldCalculation();
    }

    /// <summary>
    /// Recomputes the edges (<see cref="LeftMm"/> …) from the field length and width, and the display sizes
    /// for a drawing 500 px high (the original's for its standard window).
    /// </summary>
    public void FieldCalculation()
    {
        LeftMm = -FieldLengthXMm / 2;
        RightMm = FieldLengthXMm / 2;
        TopMm = -FieldLengthZMm / 2;
        BottomMm = FieldLengthZMm / 2;
        FieldLengthZPix = TabControlLengthZPix - (2 * FieldInnerBorderPix) - (2 * FieldOuterBorderPix);
        ScaleMmToPix = FieldLengthZPix > 0 ? (double)FieldLengthZMm / FieldLengthZPix : 1.0;
        ScaleMmToPixX = ScaleMmToPix;
        ScaleMmToPixZ = ScaleMmToPix;
        FieldLengthXPix = ToPix(FieldLengthXMm);
        GoalDepthPix = ToPix(GoalDepthMm);
        GoalWidthPix = ToPix(GoalWidthMm);
        GoalBlockWidthPix = (FieldLengthZPix - GoalWidthPix) / 2;
        GoalBlockDepthPix = GoalDepthPix;
        int frame = (2 * FieldInnerBorderPix) + (2 * FieldOuterBorderPix);
        PictureBoxXPix = FieldLengthXPix + frame;
        PictureBoxZPix = FieldLengthZPix + frame;
        FormLengthXPix = TabControlLengthXPix + FieldLengthXPix + SpanBetweenFieldAndTabControlPix + frame + (2 * FormPaddingPix);
        FormLengthZPix = TabControlLengthZPix + (2 * FormPaddingPix);
        ForbiddenZoneLengthXPix = ToPix(ForbiddenZoneLengthXMm);
        ForbiddenZoneLengthZPix = ToPix(ForbiddenZoneLengthZMm);
        CenterCircleRadiusPix = ToPix(CenterCircleRadiusMm);
        MovingCircleRadiusPix = ToPix(MovingCircleRadiusMm);
        OffsetHeightPix = ToPix(OffsetHeightMm);
        OffsetWidthPix = ToPix(OffsetWidthMm);
        FieldCenterXPix = FieldOuterBorderPix + FieldInnerBorderPix + (FieldLengthXPix / 2);
        FieldCenterZPix = FieldOuterBorderPix + FieldInnerBorderPix + (FieldLengthZPix / 2);
    }

    /// <summary>An X in mm as a pixel column of the original's display.</summary>
    /// <param name="mm">X, mm.</param>
    /// <returns>Pixel column.</returns>
    public int MmToPixX(int mm) => (int)((mm / ScaleMmToPixX) + 0.5) + FieldCenterXPix;

    /// <summary>A Z in mm as a pixel row of the original's display.</summary>
    /// <param name="mm">Z, mm.</param>
    /// <returns>Pixel row.</returns>
    public int MmToPixZ(int mm) => (int)((mm / ScaleMmToPixZ) + 0.5) + FieldCenterZPix;

    /// <summary>A field point (X, Z) in mm as a display point.</summary>
    /// <param name="pointMm">(X, Z), mm.</param>
    /// <returns>Display point, px.</returns>
    public Point MmToPix(Point pointMm) => new(MmToPixX(pointMm.X), MmToPixZ(pointMm.Y));

    /// <summary>A field point in mm as a display point (Y = 0).</summary>
    /// <param name="vector3">Field point, mm.</param>
    /// <returns>Display point, px.</returns>
    public Xna.Vector3 MmToPix(Xna.Vector3 vector3) => new(MmToPixX((int)vector3.X), 0f, MmToPixZ((int)vector3.Z));

    /// <summary>
    /// A field rectangle given by its top-left corner and size in mm as a display rectangle: the corner through
    /// <see cref="MmToPixX"/>/<see cref="MmToPixZ"/>, the size scaled the same way (display only).
    /// </summary>
    /// <param name="xMm">Left X, mm.</param>
    /// <param name="zMm">Top Z, mm.</param>
    /// <param name="widthMm">Width along X, mm.</param>
    /// <param name="heightMm">Height along Z, mm.</param>
    /// <returns>The display rectangle, px.</returns>
    public Rectangle MmToPix(int xMm, int zMm, int widthMm, int heightMm) =>
        new(MmToPixX(xMm), MmToPixZ(zMm), MmToPixX(widthMm) - FieldCenterXPix, MmToPixZ(heightMm) - FieldCenterZPix);

    /// <summary>A field rectangle in mm (X right, Z down) as a display rectangle (display only).</summary>
    /// <param name="rectMm">The rectangle, mm.</param>
    /// <returns>The display rectangle, px.</returns>
    public Rectangle MmToPix(Rectangle rectMm) => MmToPix(rectMm.Left, rectMm.Top, rectMm.Width, rectMm.Height);

    /// <summary>A display point as a field point (X, Z) in mm.</summary>
    /// <param name="pointPix">Display point, px.</param>
    /// <returns>(X, Z), mm.</returns>
    public Point PixToMm(Point pointPix) =>
        new((int)((pointPix.X - FieldCenterXPix) * ScaleMmToPixX), (int)((pointPix.Y - FieldCenterZPix) * ScaleMmToPixZ));

    /// <summary>A display point as a field point in mm (Y = 0).</summary>
    /// <param name="vector3Pix">Display point, px.</param>
    /// <returns>Field point, mm.</returns>
    public Xna.Vector3 PixToMm(Xna.Vector3 vector3Pix) =>
        new((float)((vector3Pix.X - FieldCenterXPix) * ScaleMmToPixX), 0f, (float)((vector3Pix.Z - FieldCenterZPix) * ScaleMmToPixZ));

    /// <summary>The field itself (there is one per process).</summary>
    /// <returns>This instance.</returns>
    public virtual object Clone() => this;

    /// <summary>Sets the field size (mm) and everything derived from it.</summary>
    /// <param name="lengthXMm">Length along X, mm.</param>
    /// <param name="lengthZMm">Width along Z, mm.</param>
    internal void SetSize(int lengthXMm, int lengthZMm)
    {
        if (FieldLengthXMm == lengthXMm && FieldLengthZMm == lengthZMm)
        {
            return;
        }

        FieldLengthXMm = lengthXMm;
        FieldLengthZMm = lengthZMm;
        FieldLengthXOriMm = lengthXMm;
        FieldLengthZOriMm = lengthZMm;
        FieldCalculation();
    }

    private int ToPix(int mm) => (int)((mm / ScaleMmToPix) + 0.5);
}
