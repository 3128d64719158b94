namespace URWPGSim2D.Server.Rendering;

/// <summary>
/// Builds an SVG document element by element, one element per line, in world millimetres
/// (x right, z down: world z is SVG's y, which already points down). Numbers are written in the
/// invariant culture with a fixed number of decimals, so the same drawing gives the same bytes
/// on every machine. Text and attribute values are XML-escaped.
/// </summary>
/// <param name="numberFormat">The .NET format of every number, e.g. <c>0.##</c> (at most two decimals).</param>
internal sealed class SvgWriter(string numberFormat)
{
    private readonly StringBuilder _text = new();

    /// <summary>Opens the document: the root element with its view box (user units = mm) and pixel size.</summary>
    /// <param name="minX">Left edge of the view box.</param>
    /// <param name="minY">Top edge of the view box (world z).</param>
    /// <param name="width">View box width.</param>
    /// <param name="height">View box height.</param>
    /// <param name="pixelWidth">Width attribute, px.</param>
    /// <param name="pixelHeight">Height attribute, px.</param>
    /// <returns>This writer.</returns>
    public SvgWriter StartDocument(float minX, float minY, float width, float height, float pixelWidth, float pixelHeight)
    {
        _text.Append("<svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"")
            .Append(Number(minX)).Append(' ').Append(Number(minY)).Append(' ').Append(Number(width)).Append(' ').Append(Number(height))
            .Append("\" width=\"").Append(Number(pixelWidth)).Append("\" height=\"").Append(Number(pixelHeight)).Append("\">\n");
        return this;
    }

    /// <summary>Closes the document.</summary>
    /// <returns>This writer.</returns>
    public SvgWriter EndDocument()
    {
        _text.Append("</svg>\n");
        return this;
    }

    /// <summary>Starts an element (<c>  &lt;name</c>); add attributes, then <see cref="End"/> or <see cref="Content"/>.</summary>
    /// <param name="name">The element name, e.g. <c>polygon</c>.</param>
    /// <returns>This writer.</returns>
    public SvgWriter Element(string name)
    {
        _text.Append("  <").Append(name);
        return this;
    }

    /// <summary>Adds a text attribute (escaped).</summary>
    /// <param name="name">The attribute name.</param>
    /// <param name="value">Its value.</param>
    /// <returns>This writer.</returns>
    public SvgWriter Attribute(string name, string value)
    {
        _text.Append(' ').Append(name).Append("=\"");
        Escape(value);
        _text.Append('"');
        return this;
    }

    /// <summary>Adds a number attribute in the writer's format.</summary>
    /// <param name="name">The attribute name.</param>
    /// <param name="value">Its value (mm for coordinates).</param>
    /// <returns>This writer.</returns>
    public SvgWriter Attribute(string name, float value)
    {
        _text.Append(' ').Append(name).Append("=\"").Append(Number(value)).Append('"');
        return this;
    }

    /// <summary>Adds a <c>points</c> attribute: <c>x,z x,z ...</c>.</summary>
    /// <param name="points">The points, mm (X = world X, Y = world Z).</param>
    /// <returns>This writer.</returns>
    public SvgWriter Points(ReadOnlySpan<Vector2> points)
    {
        _text.Append(" points=\"");
        for (int i = 0; i < points.Length; i++)
        {
            _text.Append(i == 0 ? string.Empty : " ").Append(Number(points[i].X)).Append(',').Append(Number(points[i].Y));
        }

        _text.Append('"');
        return this;
    }

    /// <summary>Ends the start tag of a container element (<c>&gt;</c> and a newline); close it with <see cref="CloseGroup"/>.</summary>
    public void Open() => _text.Append(">\n");

    /// <summary>Closes a <c>g</c> element opened with <see cref="Element"/> and <see cref="Open"/>.</summary>
    public void CloseGroup() => _text.Append("  </g>\n");

    /// <summary>Ends an empty element: <c>/&gt;</c> and a newline.</summary>
    public void End() => _text.Append("/>\n");

    /// <summary>Ends the start tag, writes escaped text content and the end tag of element <paramref name="name"/>.</summary>
    /// <param name="name">The element name given to <see cref="Element"/>.</param>
    /// <param name="content">The text.</param>
    public void Content(string name, string content)
    {
        _text.Append('>');
        Escape(content);
        _text.Append("</").Append(name).Append(">\n");
    }

    /// <summary>A number in the writer's format, invariant culture; negative zero is written as 0.</summary>
    /// <param name="value">The value.</param>
    /// <returns>Its text.</returns>
    public string Number(float value)
    {
        string text = value.ToString(numberFormat, CultureInfo.InvariantCulture);
        return text == "-0" ? "0" : text;
    }

    /// <summary>The document written so far.</summary>
    /// <returns>The SVG text.</returns>
    public override string ToString() => _text.ToString();

    private void Escape(string value)
    {
        foreach (char c in value)
        {
            _ = c switch
            {
                '&' => _text.Append("&amp;"),
                '<' => _text.Append("&lt;"),
                '>' => _text.Append("&gt;"),
                '"' => _text.Append("&quot;"),
                _ => _text.Append(c),
            };
        }
    }
}
