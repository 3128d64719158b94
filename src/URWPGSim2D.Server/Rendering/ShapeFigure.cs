using URWPGSim2D.Collision;
using URWPGSim2D.Collision.Fish;
using URWPGSim2D.Collision.Geometry;
using URWPGSim2D.Collision.Shapes;
using URWPGSim2D.Engine.Trace;

namespace URWPGSim2D.Server.Rendering;

/// <summary>
/// An SVG picture of input shapes and pair results, in world millimetres (+X right, +Z down:
/// world z is SVG's y). A fish shows its eight leaf polygons, each leaf's 8-DOP and the three
/// circles of its tree (root, body group, tail group); another shape shows itself and its outer
/// circle; an intersecting pair shows its MTV (true length, from the action point), its normal
/// (a fixed fraction of the picture) and its action point. The view box fits the content with
/// an 8 % margin; a legend panel sits on the right. Output is deterministic (invariant culture,
/// three decimals).
/// </summary>
internal static class ShapeFigure
{
    private const float ContentPixels = 720f;
    private const float MarginFraction = 0.08f;
    private const float NormalFraction = 0.12f;
    private const string NumberFormat = "0.###";

    /// <summary>Draws the shapes and contacts.</summary>
    /// <param name="shapes">The shapes, drawn in order (later on top).</param>
    /// <param name="contacts">The pair results; only intersecting ones are drawn.</param>
    /// <returns>The SVG document.</returns>
    public static string Render(IReadOnlyList<FigureShape> shapes, IReadOnlyList<FigureContact> contacts)
    {
        var extent = new FigureExtent();
        var roles = new bool[3];
        bool anyFish = false, anyPrimitive = false, anyContact = false;
        foreach (var s in shapes)
        {
            AddShape(extent, s.Shape);
            roles[(int)s.Role] = true;
            anyFish |= s.Shape.IsFish;
            anyPrimitive |= !s.Shape.IsFish;
        }

        foreach (var c in contacts)
        {
            if (c.Contact.Intersect)
            {
                anyContact = true;
                extent.Add(ActionPoint(c));
                extent.Add(ActionPoint(c) + Mtv(c));
            }
        }

        if (extent.IsEmpty)
        {
            extent.Add(new Vector2(-100f));
            extent.Add(new Vector2(100f));
        }

        float normalLength = NormalFraction * Largest(extent.Size);
        foreach (var c in contacts)
        {
            if (c.Contact.Intersect)
            {
                extent.Add(ActionPoint(c) + (Normal(c) * normalLength));
            }
        }

        float margin = MarginFraction * Largest(extent.Size);
        Vector2 boxMin = extent.Min - new Vector2(margin);
        Vector2 boxSize = extent.Size + new Vector2(2f * margin);
        float mmPerPx = MathF.Max(boxSize.X, boxSize.Y) / ContentPixels;
        var legend = FigureLegend.For(roles, anyFish, anyPrimitive, anyContact);
        float viewWidth = boxSize.X + (FigureLegend.WidthPx * mmPerPx);
        float viewHeight = MathF.Max(boxSize.Y, legend.HeightPx * mmPerPx);

        var writer = new SvgWriter(NumberFormat).StartDocument(boxMin.X, boxMin.Y, viewWidth, viewHeight, viewWidth / mmPerPx, viewHeight / mmPerPx);
        var canvas = new FigureCanvas(writer, mmPerPx);
        canvas.Rect(FigureStyle.BackgroundClass, boxMin, new Vector2(viewWidth, viewHeight), new Stroke("none", 0f), "#ffffff");
        foreach (var s in shapes)
        {
            DrawShape(canvas, s);
        }

        foreach (var c in contacts)
        {
            if (c.Contact.Intersect)
            {
                DrawContact(canvas, writer, c, normalLength);
            }
        }

        foreach (var s in shapes)
        {
            var outer = OuterCircle(s.Shape);
            var at = outer.Center - new Vector2(0f, outer.Radius + canvas.Px(4f));
            canvas.Text(FigureStyle.LabelClass, at, s.Label, 12f, "middle", "#333", halo: true);
        }

        legend.Draw(canvas, writer, new Vector2(boxMin.X + boxSize.X, boxMin.Y));
        return writer.EndDocument().ToString();
    }

    private static void AddShape(FigureExtent extent, InputShape shape)
    {
        if (shape.IsFish)
        {
            var fish = shape.Fish;
            for (var part = FishPart.LeftPectoral; part <= FishPart.RightCaudal; part++)
            {
                extent.Add(fish.GetLeaf(part));
                extent.Add(fish.GetLeafBound(part).Vertices);
            }

            extent.Add(fish.Root);
            extent.Add(fish.BodyGroup);
            extent.Add(fish.TailGroup);
            return;
        }

        extent.Add(shape.Shape.BoundingCircle);
        extent.Add(Outline(shape.Shape));
    }

    private static void DrawShape(FigureCanvas canvas, in FigureShape s)
    {
        string fill = FigureStyle.Fill(s.Role);
        var outline = FigureStyle.Outline(s.Role);
        if (s.Shape.IsFish)
        {
            var fish = s.Shape.Fish;
            for (var part = FishPart.LeftPectoral; part <= FishPart.RightCaudal; part++)
            {
                canvas.Polygon(FigureStyle.LeafClass, fish.GetLeaf(part), outline, fill, FigureStyle.FillOpacity);
            }

            for (var part = FishPart.LeftPectoral; part <= FishPart.RightCaudal; part++)
            {
                canvas.Polygon(FigureStyle.KDopClass, fish.GetLeafBound(part).Vertices, FigureStyle.KDop, "none");
            }

            canvas.Circle(FigureStyle.BodyGroupClass, fish.BodyGroup.Center, fish.BodyGroup.Radius, FigureStyle.BodyGroup, "none");
            canvas.Circle(FigureStyle.TailGroupClass, fish.TailGroup.Center, fish.TailGroup.Radius, FigureStyle.TailGroup, "none");
            canvas.Circle(FigureStyle.RootClass, fish.Root.Center, fish.Root.Radius, FigureStyle.Root, "none");
            return;
        }

        ref readonly Shape shape = ref s.Shape.Shape;
        var points = Outline(shape);
        if (shape.Kind == ShapeKind.Circle)
        {
            var circle = shape.AsCircle();
            canvas.Circle(FigureStyle.ShapeClass, circle.Center, circle.Radius, outline, fill, FigureStyle.FillOpacity);
        }
        else if (points.Length >= 3)
        {
            canvas.Polygon(FigureStyle.ShapeClass, points, outline, fill, FigureStyle.FillOpacity);
        }
        else if (points.Length == 2)
        {
            canvas.Line(FigureStyle.ShapeClass, points[0], points[1], outline with { WidthPx = 2.5f });
        }
        else
        {
            canvas.Circle(FigureStyle.ShapeClass, points[0], canvas.Px(2f), outline, outline.Colour);
        }

        var outer = shape.BoundingCircle;
        canvas.Circle(FigureStyle.OuterClass, outer.Center, outer.Radius, FigureStyle.Outer, "none");
    }

    private static void DrawContact(FigureCanvas canvas, SvgWriter writer, in FigureContact c, float normalLength)
    {
        Vector2 at = ActionPoint(c);
        canvas.Arrow(FigureStyle.NormalClass, at, at + (Normal(c) * normalLength), FigureStyle.Normal);
        canvas.Arrow(FigureStyle.MtvClass, at, at + Mtv(c), FigureStyle.Mtv);
        canvas.Circle(FigureStyle.ActionPointClass, at, canvas.Px(3.5f), FigureStyle.ActionPoint, FigureStyle.ActionPointFill);
        Vector2 mtv = Mtv(c);
        string text = string.Create(CultureInfo.InvariantCulture, $"{c.Label}: mtv [{writer.Number(mtv.X)}, {writer.Number(mtv.Y)}]");
        if (c.HasParts)
        {
            text += $", parts {FishPartNames.OfOptional(c.Contact.PartA) ?? "-"} / {FishPartNames.OfOptional(c.Contact.PartB) ?? "-"}";
        }

        canvas.Text(FigureStyle.AnnotationClass, at + new Vector2(canvas.Px(8f), canvas.Px(16f)), text, 11f, colour: "#b10026", halo: true);
    }

    // The vertices a primitive shape is drawn with (empty for a circle).
    private static Vector2[] Outline(in Shape shape) => shape.Kind switch
    {
        ShapeKind.Aabb => ShapePiecesDto.Corners(shape.AsAabb()),
        ShapeKind.KDop8 => shape.AsKDop8().Vertices.ToArray(),
        ShapeKind.Polygon => shape.AsPolygon().Vertices.ToArray(),
        ShapeKind.Segment => [shape.AsSegment().A, shape.AsSegment().B],
        _ => [],
    };

    private static Circle OuterCircle(InputShape shape) => shape.IsFish ? shape.Fish.Root : shape.Shape.BoundingCircle;

    private static Vector2 ActionPoint(in FigureContact c) => XZPlane.ToPlane(c.Contact.Result.ActionPoint);

    private static Vector2 Mtv(in FigureContact c) => XZPlane.ToPlane(c.Contact.Result.MinimumTranslationVector);

    private static Vector2 Normal(in FigureContact c) => XZPlane.ToPlane(c.Contact.Result.NormalAxis);

    private static float Largest(Vector2 size) => MathF.Max(MathF.Max(size.X, size.Y), 1f);
}
