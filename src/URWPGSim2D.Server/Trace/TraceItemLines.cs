using System.Numerics;
using System.Text.Json;
using URWPGSim2D.Server.Items;
using URWPGSim2D.Server.Simulation;

namespace URWPGSim2D.Server.Trace;

/// <summary>
/// The trace's item members (the contract shared by the viewer and the items): <c>score</c> and
/// <c>events</c> on every line, and on the cycle-0 line <c>item</c> and <c>layout</c> (field, goals,
/// goal blocks, obstacles, zones, teams, fish sizes, balls with radius and value).
/// </summary>
internal static class TraceItemLines
{
    /// <summary>Writes the members into the open line object.</summary>
    public static void Write(Utf8JsonWriter w, World world, ITraceItemInfo item)
    {
        w.WriteStartArray("score");
        foreach (int score in item.TeamScores)
        {
            w.WriteNumberValue(score);
        }

        w.WriteEndArray();
        w.WriteStartArray("events");
        foreach (ref readonly var e in item.CycleEvents)
        {
            Event(w, e);
        }

        w.WriteEndArray();
        if (world.Cycle == 0)
        {
            w.WriteString("item", item.ItemSlug);
            Layout(w, world, item);
        }
    }

    private static void Event(Utf8JsonWriter w, in ItemEvent e)
    {
        w.WriteStartObject();
        w.WriteString("kind", e.Kind);
        if (e.Team >= 0)
        {
            w.WriteNumber("team", e.Team);
        }

        if (e.Fish >= 0)
        {
            w.WriteNumber("fish", e.Fish);
        }

        if (e.Ball >= 0)
        {
            w.WriteNumber("ball", e.Ball);
        }

        if (!double.IsNaN(e.Value))
        {
            w.WriteNumber("value", e.Value);
        }

        w.WriteString("text", e.Text);
        w.WriteEndObject();
    }

    private static void Layout(Utf8JsonWriter w, World world, ITraceItemInfo item)
    {
        var field = world.Field;
        w.WriteStartObject("layout");
        w.WriteStartObject("field");
        w.WriteNumber("length", field.Length);
        w.WriteNumber("width", field.Width);
        w.WriteEndObject();
        w.WriteStartArray("goals");
        if (item.ItemSlug == "default")
        {
            // The plain rules' goal mouths: the left one is defended by team 1's opponents' target, i.e. team 1 scores there.
            float x = field.Length * 0.5f, depth = Collision.Pool.Field.GoalDepth, half = Collision.Pool.Field.GoalWidth * 0.5f;
            Box(w, "team", 0, new Vector2(-x, -half), new Vector2(-x + depth, half));
            Box(w, "team", 1, new Vector2(x - depth, -half), new Vector2(x, half));
        }

        w.WriteEndArray();
        w.WriteStartArray("goalBlocks");
        foreach (var block in field.GoalBlocks)
        {
            Box(w, null, 0, block.Min, block.Max);
        }

        w.WriteEndArray();
        w.WriteStartArray("obstacles");
        foreach (var o in world.Obstacles)
        {
            w.WriteStartObject();
            if (o.Kind == ObstacleKind.Round)
            {
                w.WriteString("type", "round");
                Pair(w, "center", o.Center);
                w.WriteNumber("radius", o.Radius);
            }
            else
            {
                w.WriteString("type", "rectangle");
                Pair(w, "center", o.Center);
                w.WriteNumber("length", o.Length);
                w.WriteNumber("width", o.Width);
                w.WriteNumber("heading", o.Heading);
            }

            w.WriteEndObject();
        }

        w.WriteEndArray();
        w.WriteStartArray("zones");
        foreach (var z in item.Zones)
        {
            w.WriteStartObject();
            w.WriteString("kind", z.Kind);
            w.WriteNumber("id", z.Id);
            if (z.Team >= 0)
            {
                w.WriteNumber("team", z.Team);
            }

            if (z.Shape == ZoneShape.Circle)
            {
                Pair(w, "center", z.Center);
                w.WriteNumber("radius", z.Radius);
            }
            else
            {
                Pair(w, "min", z.Min);
                Pair(w, "max", z.Max);
            }

            w.WriteEndObject();
        }

        w.WriteEndArray();
        w.WriteStartArray("teams");
        for (int t = 0; t < item.TeamScores.Length; t++)
        {
            w.WriteStartObject();
            w.WriteNumber("id", t);
            w.WriteEndObject();
        }

        w.WriteEndArray();
        w.WriteStartArray("fish");
        var perTeam = new int[item.TeamScores.Length + 1];
        foreach (var f in world.Fish)
        {
            w.WriteStartObject();
            w.WriteNumber("team", f.Team);
            w.WriteNumber("index", perTeam[System.Math.Min(f.Team, perTeam.Length - 1)]++);
            w.WriteStartObject("size");
            w.WriteNumber("length", f.Size.Length);
            w.WriteNumber("width", f.Size.Width);
            w.WriteNumber("head", f.Size.Head);
            w.WriteStartArray("joints");
            w.WriteNumberValue(f.Size.Joint1);
            w.WriteNumberValue(f.Size.Joint2);
            w.WriteNumberValue(f.Size.Joint3);
            w.WriteEndArray();
            w.WriteEndObject();
            w.WriteEndObject();
        }

        w.WriteEndArray();
        w.WriteStartArray("balls");
        for (int i = 0; i < world.Balls.Length; i++)
        {
            w.WriteStartObject();
            w.WriteNumber("radius", world.Balls[i].Radius);
            double value = item.BallValue(i);
            if (!double.IsNaN(value))
            {
                w.WriteNumber("value", value);
            }

            w.WriteEndObject();
        }

        w.WriteEndArray();
        w.WriteEndObject();
    }

    private static void Box(Utf8JsonWriter w, string? teamName, int team, Vector2 min, Vector2 max)
    {
        w.WriteStartObject();
        if (teamName is not null)
        {
            w.WriteNumber(teamName, team);
        }

        Pair(w, "min", min);
        Pair(w, "max", max);
        w.WriteEndObject();
    }

    private static void Pair(Utf8JsonWriter w, string name, Vector2 v)
    {
        w.WriteStartArray(name);
        w.WriteNumberValue(v.X);
        w.WriteNumberValue(v.Y);
        w.WriteEndArray();
    }
}
