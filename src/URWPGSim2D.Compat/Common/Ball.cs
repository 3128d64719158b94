namespace URWPGSim2D.Common;

/// <summary>A ball.</summary>
[Serializable]
public class Ball : RoundedDynamic
{
    /// <summary>Creates a ball of radius 58 mm at the centre.</summary>
    public Ball()
    {
        SetBall();
    }

    /// <summary>Creates a ball of the given radius.</summary>
    /// <param name="radiusMm">Radius, mm.</param>
    public Ball(int radiusMm)
    {
        SetBall();
        RadiusMm = radiusMm;
    }

    /// <summary>Creates a ball of the given radius and colour.</summary>
    /// <param name="radiusMm">Radius, mm.</param>
    /// <param name="color">Border and fill colour.</param>
    public Ball(int radiusMm, Color color)
    {
        SetBall();
        RadiusMm = radiusMm;
        ColorBorder = color;
        ColorFilled = color;
    }

    /// <summary>Trajectory points of the original's display (empty).</summary>
    public List<Point> TrajectoryPoints = new();

    /// <summary>Sets the default ball: radius 58 mm, pink border, black fill, at the centre.</summary>
    public void SetBall()
    {
        RadiusMm = 58;
        ColorBorder = Color.Pink;
        ColorFilled = Color.Black;
        PositionMm = default;
    }

    /// <inheritdoc/>
    public override object Clone()
    {
        var copy = new Ball();
        CopyTo(copy);
        return copy;
    }
}
