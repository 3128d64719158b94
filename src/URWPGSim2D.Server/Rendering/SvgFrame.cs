using System;
using System.Globalization;
using System.IO;
using System.Numerics;
using System.Text;
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
        var s = new StringBuilder();
        s.Append("<svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"")
            .Append(N(-l / 2 - 20)).Append(' ').Append(N(-w / 2 - 90)).Append(' ').Append(N(l + 40)).Append(' ').Append(N(w + 110))
            .Append("\" width=\"").Append(N((l + 40) / 3)).Append("\" height=\"").Append(N((w + 110) / 3)).Append("\">\n");
        s.Append("  <text x=\"").Append(N(-l / 2)).Append("\" y=\"").Append(N(-w / 2 - 30)).Append("\" font-size=\"50\" font-family=\"sans-serif\">cycle ")
            .Append(world.Cycle.ToString(CultureInfo.InvariantCulture)).Append(" — team 0: ").Append(world.Goals[0].ToString(CultureInfo.InvariantCulture))
            .Append(", team 1: ").Append(world.Goals[1].ToString(CultureInfo.InvariantCulture)).Append("</text>\n");
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

        s.Append("</svg>\n");
        return s.ToString();
    }

    /// <summary>Writes the frame to a file (temporary name, then renamed).</summary>
    public static void Write(World world, string path)
    {
        string full = Path.GetFullPath(path);
        string temporary = full + ".partial";
        File.WriteAllText(temporary, Render(world), new UTF8Encoding(false));
        File.Move(temporary, full, overwrite: true);
    }

    private static void Rect(StringBuilder s, Vector2 min, Vector2 max, string fill, string stroke) =>
        s.Append("  <rect x=\"").Append(N(min.X)).Append("\" y=\"").Append(N(min.Y)).Append("\" width=\"").Append(N(max.X - min.X))
            .Append("\" height=\"").Append(N(max.Y - min.Y)).Append("\" fill=\"").Append(fill).Append("\" stroke=\"").Append(stroke).Append("\" stroke-width=\"4\"/>\n");

    private static void Circle(StringBuilder s, Vector2 c, float r, string fill) =>
        s.Append("  <circle cx=\"").Append(N(c.X)).Append("\" cy=\"").Append(N(c.Y)).Append("\" r=\"").Append(N(r)).Append("\" fill=\"").Append(fill).Append("\"/>\n");

    private static void Polygon(StringBuilder s, ReadOnlySpan<Vector2> points, string fill)
    {
        s.Append("  <polygon points=\"");
        for (int i = 0; i < points.Length; i++)
        {
            s.Append(i == 0 ? string.Empty : " ").Append(N(points[i].X)).Append(',').Append(N(points[i].Y));
        }

        s.Append("\" fill=\"").Append(fill).Append("\" stroke=\"#222\" stroke-width=\"1\"/>\n");
    }

    private static string N(float v) => v.ToString("0.##", CultureInfo.InvariantCulture);
}
