namespace URWPGSim2D.Server.Rendering;

/// <summary>How an outline is drawn: colour, width in pixels, and an optional dash (dash, gap) in pixels.</summary>
/// <param name="Colour">An SVG colour, e.g. <c>#08519c</c>, or <c>none</c>.</param>
/// <param name="WidthPx">Line width, px.</param>
/// <param name="DashPx">Dash and gap lengths, px; null for a solid line.</param>
internal readonly record struct Stroke(string Colour, float WidthPx, Vector2? DashPx = null);
