using URWPGSim2D.Collision.Shapes;

namespace URWPGSim2D.Server.Rendering;

/// <summary>The smallest axis-aligned box (mm) holding everything added to it: points and whole circles.</summary>
internal sealed class FigureExtent
{
    /// <summary>The lower corner (x, z); +∞ while empty.</summary>
    public Vector2 Min { get; private set; } = new(float.PositiveInfinity);

    /// <summary>The upper corner (x, z); −∞ while empty.</summary>
    public Vector2 Max { get; private set; } = new(float.NegativeInfinity);

    /// <summary>Whether nothing has been added.</summary>
    public bool IsEmpty => Min.X > Max.X;

    /// <summary>Width × height of the box (0 × 0 while empty), mm.</summary>
    public Vector2 Size => IsEmpty ? Vector2.Zero : Max - Min;

    /// <summary>Adds a point.</summary>
    /// <param name="point">The point, mm.</param>
    public void Add(Vector2 point)
    {
        Min = Vector2.Min(Min, point);
        Max = Vector2.Max(Max, point);
    }

    /// <summary>Adds points.</summary>
    /// <param name="points">The points, mm.</param>
    public void Add(ReadOnlySpan<Vector2> points)
    {
        foreach (var p in points)
        {
            Add(p);
        }
    }

    /// <summary>Adds a whole circle (its bounding square).</summary>
    /// <param name="circle">The circle.</param>
    public void Add(in Circle circle)
    {
        Add(circle.Center - new Vector2(circle.Radius));
        Add(circle.Center + new Vector2(circle.Radius));
    }
}
