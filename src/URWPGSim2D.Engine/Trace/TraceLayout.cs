using System.Text.Json;
using URWPGSim2D.Collision.Pool;
using URWPGSim2D.Engine.Teams;

namespace URWPGSim2D.Engine.Trace;

/// <summary>
/// Writes the static <c>layout</c> object of the cycle-0 line: field size, goal mouths (with the
/// team that defends each), goal blocks, obstacles (index = obstacleN), the item's zones, the
/// teams, and every fish's team, index in its team and size, and every ball's radius and value,
/// in the order of every line's <c>fish</c> and <c>balls</c>.
/// </summary>
internal static class TraceLayout
{
    /// <summary>Writes the layout object as the writer's next value.</summary>
    public static void Write(Utf8JsonWriter w, World world, IMatchTeams teams, ITraceItemInfo item)
    {
        var field = world.Field;
        float halfLength = field.Length / 2, halfWidth = field.Width / 2, mouth = Field.GoalWidth / 2;
        w.WriteStartObject();
        w.WriteStartObject("field");
        w.WriteNumber("length", field.Length);
        w.WriteNumber("width", field.Width);
        w.WriteEndObject();

        // Team 0 attacks the right goal (World.ScoringTeam), so it defends the left one.
        w.WriteStartArray("goals");
        for (int side = -1; side <= 1; side += 2)
        {
            w.WriteStartObject();
            w.WriteNumber("team", 1 - World.ScoringTeam(side));
            float inner = side * (halfLength - Field.GoalDepth), outer = side * halfLength;
            TraceLine.Pair(w, "min", new Vector2(MathF.Min(inner, outer), -mouth));
            TraceLine.Pair(w, "max", new Vector2(MathF.Max(inner, outer), mouth));
            w.WriteEndObject();
        }

        w.WriteEndArray();
        w.WriteStartArray("goalBlocks");
        foreach (var block in field.GoalBlocks)
        {
            w.WriteStartObject();
            TraceLine.Pair(w, "min", block.Min);
            TraceLine.Pair(w, "max", block.Max);
            w.WriteEndObject();
        }

        w.WriteEndArray();
        w.WriteStartArray("obstacles");
        foreach (var o in world.Obstacles)
        {
            w.WriteStartObject();
            if (o.Kind == ObstacleKind.Round)
            {
                w.WriteString("type", "round");
                TraceLine.Pair(w, "center", o.Center);
                w.WriteNumber("radius", o.Radius);
            }
            else
            {
                w.WriteString("type", "rectangle");
                TraceLine.Pair(w, "center", o.Center);
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
            WriteZone(w, z);
        }

        w.WriteEndArray();
        w.WriteStartArray("teams");
        int teamCount = world.TeamCount;
        for (int team = 0; team < teamCount; team++)
        {
            w.WriteStartObject();
            w.WriteNumber("id", team);
            w.WriteString("name", teams.TeamLabel(team));
            w.WriteEndObject();
        }

        w.WriteEndArray();
        w.WriteStartArray("fish");
        Span<int> inTeam = stackalloc int[teamCount];
        foreach (var f in world.Fish)
        {
            w.WriteStartObject();
            w.WriteNumber("team", f.Team);
            w.WriteNumber("index", (uint)f.Team < (uint)teamCount ? inTeam[f.Team]++ : 0);
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
        foreach (var b in world.Balls)
        {
            w.WriteStartObject();
            w.WriteNumber("radius", b.Radius);
            if (item.BallValue(b.Index) is double value)
            {
                w.WriteNumber("value", value);
            }

            w.WriteEndObject();
        }

        w.WriteEndArray();
        w.WriteEndObject();
    }

    private static void WriteZone(Utf8JsonWriter w, TraceZone z)
    {
        w.WriteStartObject();
        w.WriteString("kind", z.Kind);
        w.WriteNumber("id", z.Id);
        if (z.Team is int team)
        {
            w.WriteNumber("team", team);
        }

        switch (z.Shape)
        {
            case TraceZoneShape.Circle:
                TraceLine.Pair(w, "center", z.Center);
                w.WriteNumber("radius", z.Radius);
                break;
            case TraceZoneShape.Box:
                TraceLine.Pair(w, "min", z.Min);
                TraceLine.Pair(w, "max", z.Max);
                break;
            default:
                w.WriteStartArray("polygon");
                foreach (var p in z.Points)
                {
                    w.WriteStartArray();
                    w.WriteNumberValue(p.X);
                    w.WriteNumberValue(p.Y);
                    w.WriteEndArray();
                }

                w.WriteEndArray();
                break;
        }

        w.WriteEndObject();
    }
}
