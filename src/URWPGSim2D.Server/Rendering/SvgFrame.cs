using URWPGSim2D.Collision.Fish;
using URWPGSim2D.Collision.Pool;
using URWPGSim2D.Engine.Simulation;
using URWPGSim2D.Tournament.Batch;

namespace URWPGSim2D.Server.Rendering;

/// <summary>
/// Draws one frame of the match as SVG in world millimetres (x right, z down, as in the pool):
/// water, goal mouths, goal blocks, obstacles, balls and every fish's eight leaf polygons
/// (team 0 red, team 1 blue, teams 2 and 3 green and purple) with a heading line, the ids (fishN above each fish, the ball's
/// number on each ball), the cycle and score as a caption and a legend of the colours. The picture
/// shows the pool, grown to take in any body outside it (a fish an item parks off the field).
/// </summary>
internal static class SvgFrame
{
    private static readonly string[] TeamColours = ["#d9483b", "#2f6fd6", "#2e9e5b", "#9b51c9"];

    /// <summary>Fill of the balls.</summary>
    private const string BallColour = "#f29b30";

    /// <summary>Fill of the obstacles.</summary>
    private const string ObstacleColour = "#6b5b4b";

    /// <summary>Room kept round a body off the pool (its id above it, its heading line), mm.</summary>
    private const float OffPoolMargin = 200f;

    /// <summary>The SVG document of the world's current state.</summary>
    /// <param name="world">The world.</param>
    /// <param name="scores">Each team's score (team 0 first; a team past the end has 0).</param>
    /// <param name="teamNames">The teams' names for the legend (team 0 first), or null for none.</param>
    public static string Render(World world, System.Collections.Generic.IReadOnlyList<int> scores, System.Collections.Generic.IReadOnlyList<string>? teamNames = null)
    {
        var field = world.Field;
        float l = field.Length;
        float w = field.Width;
        var (min, max) = Drawn(world);
        float top = min.Y;
        var s = new SvgWriter("0.##");
        s.StartDocument(min.X - 20, top - 170, max.X - min.X + 40, max.Y - min.Y + 190, (max.X - min.X + 40) / 3, (max.Y - min.Y + 190) / 3);
        s.Element("text").Attribute("x", min.X).Attribute("y", top - 110).Attribute("font-size", "50").Attribute("font-family", "sans-serif")
            .Content("text", Caption(world, scores));
        Legend(s, world, scores, teamNames, min.X, top - 45);
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
                Circle(s, o.Center, o.Radius, ObstacleColour);
            }
            else
            {
                Vector2 u = new(MathF.Cos(o.Heading), MathF.Sin(o.Heading));
                Vector2 n = new(-u.Y, u.X);
                Vector2 a = u * (o.Length / 2);
                Vector2 b = n * (o.Width / 2);
                Polygon(s, [o.Center + a + b, o.Center - a + b, o.Center - a - b, o.Center + a - b], ObstacleColour);
            }
        }

        foreach (var b in world.Balls)
        {
            Circle(s, b.Position, b.Radius, BallColour);
        }

        foreach (var f in world.Fish)
        {
            string colour = TeamColours[f.Team % TeamColours.Length];
            var model = new FishModel(f.Size, f.Pose);
            for (var part = FishPart.LeftPectoral; part <= FishPart.RightCaudal; part++)
            {
                Polygon(s, model.GetLeaf(part), colour);
            }

            // Heading: a line ahead of the head tip.
            Vector2 tip = model.HeadTip, ahead = tip + (model.Forward * 70f);
            s.Element("line").Attribute("x1", tip.X).Attribute("y1", tip.Y).Attribute("x2", ahead.X).Attribute("y2", ahead.Y)
                .Attribute("stroke", "#111").Attribute("stroke-width", "4").End();
        }

        // Ids on top of everything: fishN above each fish's body centre, the ball's number on it.
        foreach (var f in world.Fish)
        {
            Label(s, f.Position - new Vector2(0, 75), string.Create(CultureInfo.InvariantCulture, $"fish{f.Index}"), "#111");
        }

        foreach (var b in world.Balls)
        {
            Label(s, b.Position, b.Index.ToString(CultureInfo.InvariantCulture), "#111");
        }

        return s.EndDocument().ToString();
    }

    // The region drawn below the caption: the pool, grown to hold every body outside it (a fish an
    // item parks off the field, with room for its id and heading line) — the pool alone otherwise.
    private static (Vector2 Min, Vector2 Max) Drawn(World world)
    {
        Vector2 half = new(world.Field.Length / 2, world.Field.Width / 2);
        var outside = new FigureExtent();
        foreach (var f in world.Fish)
        {
            var model = new FishModel(f.Size, f.Pose);
            for (var part = FishPart.LeftPectoral; part <= FishPart.RightCaudal; part++)
            {
                foreach (var p in model.GetLeaf(part))
                {
                    if (MathF.Abs(p.X) > half.X || MathF.Abs(p.Y) > half.Y)
                    {
                        outside.Add(f.Position - new Vector2(OffPoolMargin));
                        outside.Add(f.Position + new Vector2(OffPoolMargin));
                        outside.Add(p);
                    }
                }
            }
        }

        foreach (var b in world.Balls)
        {
            if (MathF.Abs(b.Position.X) + b.Radius > half.X || MathF.Abs(b.Position.Y) + b.Radius > half.Y)
            {
                outside.Add(new URWPGSim2D.Collision.Shapes.Circle(b.Position, b.Radius + 20f));
            }
        }

        return outside.IsEmpty ? (-half, half) : (Vector2.Min(-half, outside.Min), Vector2.Max(half, outside.Max));
    }

    // The key: each team's colour, name and score, then the ball and obstacle colours.
    private static void Legend(SvgWriter s, World world, System.Collections.Generic.IReadOnlyList<int> scores, System.Collections.Generic.IReadOnlyList<string>? teamNames, float x, float y)
    {
        int teams = world.TeamCount;
        for (int team = 0; team < teams; team++)
        {
            s.Element("rect").Attribute("x", x).Attribute("y", y - 35).Attribute("width", 40).Attribute("height", 40)
                .Attribute("fill", TeamColours[team]).Attribute("stroke", "#222").Attribute("stroke-width", "2").End();
            string name = teamNames is not null && team < teamNames.Count ? $" ({teamNames[team]})" : string.Empty;
            string text = string.Create(CultureInfo.InvariantCulture, $"team {team}{name}: {Goals(scores, team)}");
            s.Element("text").Attribute("x", x + 55).Attribute("y", y).Attribute("font-size", "40").Attribute("font-family", "sans-serif").Content("text", text);
            x += 130 + (22 * text.Length);
        }

        s.Element("circle").Attribute("cx", x + 20).Attribute("cy", y - 15).Attribute("r", 20).Attribute("fill", BallColour).End();
        s.Element("text").Attribute("x", x + 55).Attribute("y", y).Attribute("font-size", "40").Attribute("font-family", "sans-serif").Content("text", "ball");
        x += 180;
        s.Element("rect").Attribute("x", x).Attribute("y", y - 35).Attribute("width", 40).Attribute("height", 40).Attribute("fill", ObstacleColour).End();
        s.Element("text").Attribute("x", x + 55).Attribute("y", y).Attribute("font-size", "40").Attribute("font-family", "sans-serif").Content("text", "obstacle");
    }

    // The caption: the cycle and every team's score.
    private static string Caption(World world, System.Collections.Generic.IReadOnlyList<int> scores)
    {
        var text = new System.Text.StringBuilder(string.Create(CultureInfo.InvariantCulture, $"cycle {world.Cycle} — "));
        int teams = world.TeamCount;
        for (int team = 0; team < teams; team++)
        {
            text.Append(CultureInfo.InvariantCulture, $"{(team > 0 ? ", " : string.Empty)}team {team}: {Goals(scores, team)}");
        }

        return text.ToString();
    }

    private static int Goals(System.Collections.Generic.IReadOnlyList<int> scores, int team) => team < scores.Count ? scores[team] : 0;

    private static void Label(SvgWriter s, Vector2 at, string text, string colour) =>
        s.Element("text").Attribute("x", at.X).Attribute("y", at.Y).Attribute("font-size", "40").Attribute("font-family", "sans-serif")
            .Attribute("font-weight", "bold").Attribute("text-anchor", "middle").Attribute("dominant-baseline", "central")
            .Attribute("fill", colour).Attribute("stroke", "#ffffff").Attribute("stroke-width", "8").Attribute("paint-order", "stroke").Content("text", text);

    /// <summary>Writes the frame to a file (temporary name, then renamed; see <see cref="AtomicFile"/>).</summary>
    /// <param name="world">The world.</param>
    /// <param name="scores">Each team's score (team 0 first).</param>
    /// <param name="path">The SVG file.</param>
    /// <param name="teamNames">The teams' names for the legend, or null.</param>
    public static void Write(World world, System.Collections.Generic.IReadOnlyList<int> scores, string path, System.Collections.Generic.IReadOnlyList<string>? teamNames) =>
        AtomicFile.WriteAllText(path, Render(world, scores, teamNames));

    private static void Rect(SvgWriter s, Vector2 min, Vector2 max, string fill, string stroke) =>
        s.Element("rect").Attribute("x", min.X).Attribute("y", min.Y).Attribute("width", max.X - min.X).Attribute("height", max.Y - min.Y)
            .Attribute("fill", fill).Attribute("stroke", stroke).Attribute("stroke-width", "4").End();

    private static void Circle(SvgWriter s, Vector2 c, float r, string fill) =>
        s.Element("circle").Attribute("cx", c.X).Attribute("cy", c.Y).Attribute("r", r).Attribute("fill", fill).End();

    private static void Polygon(SvgWriter s, ReadOnlySpan<Vector2> points, string fill) =>
        s.Element("polygon").Points(points).Attribute("fill", fill).Attribute("stroke", "#222").Attribute("stroke-width", "1").End();
}
