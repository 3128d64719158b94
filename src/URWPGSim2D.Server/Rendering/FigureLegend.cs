namespace URWPGSim2D.Server.Rendering;

/// <summary>
/// The legend panel to the right of a figure: one row per kind of element the figure contains
/// (a swatch in that element's style and a short text), then the axis convention.
/// </summary>
internal sealed class FigureLegend
{
    /// <summary>The class of the legend's group element.</summary>
    public const string GroupClass = "legend";

    /// <summary>The panel's width, px.</summary>
    public const float WidthPx = 250f;

    private const float RowPx = 18f, PaddingPx = 10f, FontPx = 12f;

    private readonly List<Entry> _entries = [];

    private enum Swatch
    {
        Fill,
        Line,
        Arrow,
        Dot,
    }

    /// <summary>The panel's height, px: a title row, the entries and the axis row.</summary>
    public float HeightPx => (2 * PaddingPx) + ((_entries.Count + 2) * RowPx);

    /// <summary>The legend of a figure with the given contents.</summary>
    /// <param name="roles">Whether shapes of each role appear (indexed by <see cref="FigureRole"/>).</param>
    /// <param name="anyFish">Whether a fish appears.</param>
    /// <param name="anyPrimitive">Whether a shape that is not a fish appears.</param>
    /// <param name="anyContact">Whether an intersecting pair is drawn.</param>
    /// <returns>The legend.</returns>
    public static FigureLegend For(bool[] roles, bool anyFish, bool anyPrimitive, bool anyContact)
    {
        var legend = new FigureLegend();
        if (roles[(int)FigureRole.Single])
        {
            legend.Add(Swatch.Fill, FigureStyle.Outline(FigureRole.Single), FigureStyle.Fill(FigureRole.Single), anyFish ? "shape / fish leaf polygon" : "shape");
        }

        if (roles[(int)FigureRole.A])
        {
            legend.Add(Swatch.Fill, FigureStyle.Outline(FigureRole.A), FigureStyle.Fill(FigureRole.A), "a (moved by the MTV)");
        }

        if (roles[(int)FigureRole.B])
        {
            legend.Add(Swatch.Fill, FigureStyle.Outline(FigureRole.B), FigureStyle.Fill(FigureRole.B), "b");
        }

        if (anyFish)
        {
            legend.Add(Swatch.Line, FigureStyle.KDop, "none", "leaf 8-DOP");
            legend.Add(Swatch.Line, FigureStyle.Root, "none", "root circle (whole fish)");
            legend.Add(Swatch.Line, FigureStyle.BodyGroup, "none", "body group circle");
            legend.Add(Swatch.Line, FigureStyle.TailGroup, "none", "tail group circle");
        }

        if (anyPrimitive)
        {
            legend.Add(Swatch.Line, FigureStyle.Outer, "none", "outer circle");
        }

        if (anyContact)
        {
            legend.Add(Swatch.Arrow, FigureStyle.Mtv, "none", "MTV, true length (moves a)");
            legend.Add(Swatch.Arrow, FigureStyle.Normal, "none", "normal, b toward a (not to scale)");
            legend.Add(Swatch.Dot, FigureStyle.ActionPoint, FigureStyle.ActionPointFill, "action point");
        }

        return legend;
    }

    /// <summary>Draws the panel with its top-left corner at <paramref name="topLeft"/>.</summary>
    /// <param name="canvas">The figure's canvas.</param>
    /// <param name="writer">The document (for the group element).</param>
    /// <param name="topLeft">Top-left corner of the panel, mm.</param>
    public void Draw(FigureCanvas canvas, SvgWriter writer, Vector2 topLeft)
    {
        writer.Element("g").Attribute("class", GroupClass).Open();
        Vector2 origin = topLeft + new Vector2(canvas.Px(PaddingPx), canvas.Px(PaddingPx));
        canvas.Text("legend-title", origin + new Vector2(0f, canvas.Px(FontPx)), "legend", FontPx + 1f);
        for (int i = 0; i < _entries.Count; i++)
        {
            var row = origin + new Vector2(0f, canvas.Px((i + 1) * RowPx));
            DrawEntry(canvas, _entries[i], row);
        }

        var axes = origin + new Vector2(0f, canvas.Px(((_entries.Count + 1) * RowPx) + FontPx));
        canvas.Text("legend-text", axes, "+X right, +Z down; mm", FontPx, colour: "#444");
        writer.CloseGroup();
    }

    private static void DrawEntry(FigureCanvas canvas, Entry entry, Vector2 row)
    {
        Vector2 left = row + new Vector2(0f, canvas.Px(9f));
        Vector2 right = left + new Vector2(canvas.Px(26f), 0f);
        switch (entry.Swatch)
        {
            case Swatch.Fill:
                canvas.Rect("legend-swatch", row + new Vector2(0f, canvas.Px(3f)), new Vector2(canvas.Px(26f), canvas.Px(11f)), entry.Stroke, entry.Fill);
                break;
            case Swatch.Line:
                canvas.Line("legend-swatch", left, right, entry.Stroke);
                break;
            case Swatch.Arrow:
                canvas.Arrow("legend-swatch", left, right, entry.Stroke);
                break;
            default:
                canvas.Circle("legend-swatch", (left + right) / 2f, canvas.Px(3.5f), entry.Stroke, entry.Fill);
                break;
        }

        canvas.Text("legend-text", row + new Vector2(canvas.Px(34f), canvas.Px(FontPx + 1f)), entry.Text, FontPx);
    }

    private void Add(Swatch swatch, Stroke stroke, string fill, string text) => _entries.Add(new Entry(swatch, stroke, fill, text));

    private readonly record struct Entry(Swatch Swatch, Stroke Stroke, string Fill, string Text);
}
