namespace URWPGSim2D.Strategies;

/// <summary>One debug drawing of a strategy in one cycle (mm, X = world X, Y = world Z).</summary>
/// <param name="Kind">Point, line, circle or text.</param>
/// <param name="Fish">The fish it belongs to (index into the snapshot's fish), or −1 for the team.</param>
/// <param name="A">The point, the line's start, the circle's centre or the text's anchor.</param>
/// <param name="B">The line's end (else unused).</param>
/// <param name="Radius">The circle's radius (else 0).</param>
/// <param name="Rgb">Colour as 0xRRGGBB, or −1 for the team's colour.</param>
/// <param name="Text">The text (text only, else null).</param>
public readonly record struct DebugShape(DebugShapeKind Kind, int Fish, Vector2 A, Vector2 B, float Radius, int Rgb, string? Text);
