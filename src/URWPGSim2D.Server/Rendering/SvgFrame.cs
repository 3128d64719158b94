using System;
using System.Globalization;
using System.Numerics;
using URWPGSim2D.Collision.Fish;
using URWPGSim2D.Collision.Pool;
using URWPGSim2D.Server.Simulation;

namespace URWPGSim2D.Server.Rendering;

/// <summary>
/// Draws one frame of the match as SVG in world millimetres (x right, z down, as in the pool):
/// water, goal mouths, goal blocks, obstacles, balls and every fish's eight leaf polygons
/// (team 0 red, team 1 blue), with the cycle and score as a caption.
/// </summary>
internal static class SvgFrame
{
    private static readonly string[] TeamColours = ["#d9483b", "#2f6fd6"];

    /// <summary>The SVG document of the world's current state.</summary>
    public static string Render(World world)
    {
        var field = world.Field;
        float l = field.Length;
        float w = field.Width;
        var s = new SvgWriter("0.##");
        s.StartDocument(-l / 2 - 20, -w / 2 - 90, l + 40, w + 110, (l + 40) / 3, (w + 110) / 3);
        s.Element("text").Attribute("x", -l / 2).Attribute("y", -w / 2 - 30).Attribute("font-size", "50").Attribute("font-family", "sans-serif")
            .Content("text", string.Create(CultureInfo.InvariantCulture, $"cycle {world.Cycle} — team 0: {world.Goals[0]}, team 1: {world.Goals[1]}"));
        Rect(s, new Vector2(-l / 2, -w / 2), new Vector2(l / 2, w / 2), "#cfe8f7", "#1b3a4b");
        float mouth = Field.GoalWidth / 2;
        Rect(s, new Vector2(-l / 2, -mouth), new Vector2(-l / 2 + Field.GoalDepth, mouth), "#f6f2c4", "none");
        Rect(s, new Vector2(l / 2 - Field.GoalDepth, -mouth), new Vector2(l / 2, mouth), "#f6f2c4", "none");
        foreach (var block in field.GoalBlocks)
        {
            Rect(s, block.Min, block.Max, "#8a8f94", "#4a4f54");
        }

        foreach (var o in world.Obstacles)
        {
            if (o.Kind == ObstacleKind.Round)
            {
                Circle(s, o.Center, o.Radius, "#6b5b4b");
            }
            else
            {
                Vector2 u = new(MathF.Cos(o.Heading), MathF.Sin(o.Heading));
                Vector2 n = new(-u.Y, u.X);
                Vector2 a = u * (o.Length / 2);
                Vector2 b = n * (o.Width / 2);
                Polygon(s, [o.Center + a + b, o.Center - a + b, o.Center - a - b, o.Center + a - b], "#6b5b4b");
            }
        }

        foreach (var b in world.Balls)
        {
            Circle(s, b.Position, b.Radius, "#f29b30");
        }

        foreach (var f in world.Fish)
        {
            string colour = TeamColours[f.Team & 1];
            for (var part = FishPart.LeftPectoral; part <= FishPart.RightCaudal; part++)
            {
                Polygon(s, f.Model.GetLeaf(part), colour);
            }
        }

        return s.EndDocument().ToString();
    }

    /// <summary>Writes the frame to a file (temporary name, then renamed; see <see cref="AtomicFile"/>).</summary>
    public static void Write(World world, string path) => AtomicFile.WriteAllText(path, Render(world));

    private static void Rect(SvgWriter s, Vector2 min, Vector2 max, string fill, string stroke) =>
        s.Element("rect").Attribute("x", min.X).Attribute("y", min.Y).Attribute("width", max.X - min.X).Attribute("height", max.Y - min.Y)
            .Attribute("fill", fill).Attribute("stroke", stroke).Attribute("stroke-width", "4").End();

    private static void Circle(SvgWriter s, Vector2 c, float r, string fill) =>
        s.Element("circle").Attribute("cx", c.X).Attribute("cy", c.Y).Attribute("r", r).Attribute("fill", fill).End();

    private static void Polygon(SvgWriter s, ReadOnlySpan<Vector2> points, string fill) =>
        s.Element("polygon").Points(points).Attribute("fill", fill).Attribute("stroke", "#222").Attribute("stroke-width", "1").End();
}
