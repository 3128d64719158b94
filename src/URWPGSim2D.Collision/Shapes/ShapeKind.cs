namespace URWPGSim2D.Collision.Shapes;

/// <summary>Which of the five primitive shapes a <see cref="Shape"/> holds.</summary>
public enum ShapeKind
{
    /// <summary>A <see cref="Shapes.Circle"/>.</summary>
    Circle,

    /// <summary>An <see cref="Shapes.Aabb"/>.</summary>
    Aabb,

    /// <summary>A <see cref="Shapes.KDop8"/>.</summary>
    KDop8,

    /// <summary>A <see cref="Shapes.ConvexPolygon"/>.</summary>
    Polygon,

    /// <summary>A <see cref="Shapes.Segment"/>.</summary>
    Segment,
}
