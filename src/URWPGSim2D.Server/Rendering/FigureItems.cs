using URWPGSim2D.Collision.Fish;

namespace URWPGSim2D.Server.Rendering;

/// <summary>A shape to draw, with the label shown above it (its input path, e.g. <c>shapes[2]</c> or <c>pairs[0].a</c>).</summary>
/// <param name="Shape">The validated input shape.</param>
/// <param name="Label">The label.</param>
/// <param name="Role">Its role, which sets its colours.</param>
internal readonly record struct FigureShape(InputShape Shape, string Label, FigureRole Role);

/// <summary>The result of a pair to draw (MTV, normal and action point when it intersects), with the pair's label.</summary>
/// <param name="Contact">The contact (MTV moves a), parts set for fish sides.</param>
/// <param name="Label">The pair's input path, e.g. <c>pairs[0]</c>.</param>
/// <param name="HasParts">Whether a side is a fish (then the annotation names the parts).</param>
internal readonly record struct FigureContact(FishContact Contact, string Label, bool HasParts);
