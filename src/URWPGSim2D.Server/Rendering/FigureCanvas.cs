namespace URWPGSim2D.Server.Rendering;

/// <summary>
/// Drawing primitives of a figure in world millimetres at a known scale: line widths, dash
/// lengths, marker and font sizes are given in pixels and converted to millimetres with
/// <see cref="MillimetresPerPixel"/>, so they look the same whatever the size of the content.
/// Every element carries a <c>class</c> naming what it shows (leaf, kdop, root, ...).
/// </summary>
/// <param name="writer">The document being written.</param>
/// <param name="millimetresPerPixel">The size of one pixel in world units.</param>
internal sealed class FigureCanvas(SvgWriter writer, float millimetresPerPixel)
{
    /// <summary>The size of one output pixel, mm.</summary>
    public float MillimetresPerPixel { get; } = millimetresPerPixel;

    /// <summary>A length in pixels as millimetres.</summary>
    /// <param name="pixels">Length, px.</param>
    /// <returns>Length, mm.</returns>
    public float Px(float pixels) => pixels * MillimetresPerPixel;

    /// <summary>A closed polygon.</summary>
    public void Polygon(string cls, ReadOnlySpan<Vector2> points, in Stroke stroke, string fill, float fillOpacity = 1f)
    {
        var e = writer.Element("polygon").Attribute("class", cls).Points(points).Attribute("fill", fill);
        if (fill != "none" && fillOpacity < 1f)
        {
            e.Attribute("fill-opacity", fillOpacity);
        }

        Apply(e, stroke).End();
    }

    /// <summary>A circle.</summary>
    public void Circle(string cls, Vector2 center, float radius, in Stroke stroke, string fill, float fillOpacity = 1f)
    {
        var e = writer.Element("circle").Attribute("class", cls).Attribute("cx", center.X).Attribute("cy", center.Y).Attribute("r", radius).Attribute("fill", fill);
        if (fill != "none" && fillOpacity < 1f)
        {
            e.Attribute("fill-opacity", fillOpacity);
        }

        Apply(e, stroke).End();
    }

    /// <summary>A straight line.</summary>
    public void Line(string cls, Vector2 from, Vector2 to, in Stroke stroke) =>
        Apply(writer.Element("line").Attribute("class", cls).Attribute("x1", from.X).Attribute("y1", from.Y).Attribute("x2", to.X).Attribute("y2", to.Y), stroke).End();

    /// <summary>A rectangle (e.g. a background or a legend swatch).</summary>
    public void Rect(string cls, Vector2 min, Vector2 size, in Stroke stroke, string fill) =>
        Apply(writer.Element("rect").Attribute("class", cls).Attribute("x", min.X).Attribute("y", min.Y).Attribute("width", size.X).Attribute("height", size.Y).Attribute("fill", fill), stroke).End();

    /// <summary>
    /// An arrow from <paramref name="from"/> to <paramref name="to"/> as one path: the shaft and a
    /// filled head at <paramref name="to"/> (10 × 7 px, whatever the arrow's length).
    /// </summary>
    public void Arrow(string cls, Vector2 from, Vector2 to, in Stroke stroke)
    {
        Vector2 d = to - from;
        float length = d.Length();
        Vector2 u = length > 0f ? d / length : Vector2.UnitX;
        Vector2 side = new(-u.Y, u.X);
        Vector2 back = to - (u * Px(10f));
        Vector2 left = back + (side * Px(3.5f)), right = back - (side * Px(3.5f));
        string path = $"M {N(from)} L {N(to)} M {N(left)} L {N(to)} L {N(right)} Z";
        Apply(writer.Element("path").Attribute("class", cls).Attribute("d", path).Attribute("fill", stroke.Colour), stroke).End();
    }

    /// <summary>
    /// A text at a point; <paramref name="anchor"/> is start, middle or end. With
    /// <paramref name="halo"/> the glyphs get a white outline underneath, to stay readable over shapes.
    /// </summary>
    public void Text(string cls, Vector2 at, string text, float sizePx, string anchor = "start", string colour = "#000", bool halo = false)
    {
        writer.Element("text").Attribute("class", cls).Attribute("x", at.X).Attribute("y", at.Y).Attribute("font-size", Px(sizePx))
            .Attribute("font-family", "sans-serif").Attribute("text-anchor", anchor).Attribute("fill", colour);
        if (halo)
        {
            writer.Attribute("stroke", "#ffffff").Attribute("stroke-width", Px(3f)).Attribute("stroke-linejoin", "round").Attribute("paint-order", "stroke");
        }

        writer.Content("text", text);
    }

    private SvgWriter Apply(SvgWriter element, in Stroke stroke)
    {
        element.Attribute("stroke", stroke.Colour).Attribute("stroke-width", Px(stroke.WidthPx));
        if (stroke.DashPx is { } dash)
        {
            element.Attribute("stroke-dasharray", $"{writer.Number(Px(dash.X))} {writer.Number(Px(dash.Y))}");
        }

        return element;
    }

    private string N(Vector2 p) => $"{writer.Number(p.X)} {writer.Number(p.Y)}";
}
