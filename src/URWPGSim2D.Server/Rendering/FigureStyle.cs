namespace URWPGSim2D.Server.Rendering;

/// <summary>
/// The look of every kind of element in a figure, and the legend's wording. Each kind has an
/// SVG class of its own (also the key tests and scripts can select on).
/// </summary>
internal static class FigureStyle
{
    /// <summary>Classes of the drawn elements.</summary>
    public const string LeafClass = "leaf", KDopClass = "kdop", RootClass = "root", BodyGroupClass = "body-group", TailGroupClass = "tail-group",
        ShapeClass = "shape", OuterClass = "outer", MtvClass = "mtv", NormalClass = "normal", ActionPointClass = "action-point",
        LabelClass = "label", AnnotationClass = "annotation", BackgroundClass = "background";

    /// <summary>A leaf's 8-DOP: thin dotted purple.</summary>
    public static readonly Stroke KDop = new("#6a51a3", 1f, new Vector2(3f, 2f));

    /// <summary>The root circle (whole fish): dashed near-black.</summary>
    public static readonly Stroke Root = new("#252525", 1.5f, new Vector2(8f, 4f));

    /// <summary>The body group circle: dashed green.</summary>
    public static readonly Stroke BodyGroup = new("#238b45", 1.5f, new Vector2(6f, 3f));

    /// <summary>The tail group circle: dashed magenta.</summary>
    public static readonly Stroke TailGroup = new("#ae017e", 1.5f, new Vector2(6f, 3f));

    /// <summary>The outer circle of a primitive shape: dashed grey.</summary>
    public static readonly Stroke Outer = new("#737373", 1.2f, new Vector2(4f, 3f));

    /// <summary>The MTV arrow: thick red.</summary>
    public static readonly Stroke Mtv = new("#e31a1c", 2.5f);

    /// <summary>The normal arrow: thin black.</summary>
    public static readonly Stroke Normal = new("#000000", 1f);

    /// <summary>The action point marker's outline.</summary>
    public static readonly Stroke ActionPoint = new("#000000", 1f);

    /// <summary>The action point marker's fill.</summary>
    public const string ActionPointFill = "#ffd92f";

    /// <summary>Opacity of shape and leaf fills, so that overlaps show.</summary>
    public const float FillOpacity = 0.6f;

    /// <summary>The fill colour of a shape or leaf in a role.</summary>
    public static string Fill(FigureRole role) => role == FigureRole.B ? "#fdae6b" : "#9ecae1";

    /// <summary>The outline of a shape or leaf in a role.</summary>
    public static Stroke Outline(FigureRole role) => new(role == FigureRole.B ? "#a63603" : "#08519c", 1f);
}
