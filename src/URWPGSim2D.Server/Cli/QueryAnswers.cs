using System.Buffers;
using System.Text.Json;
using URWPGSim2D.Collision.Fish;
using URWPGSim2D.Collision.Queries;
using URWPGSim2D.Engine.Trace;

namespace URWPGSim2D.Server.Cli;

/// <summary>
/// Answers the queries of <c>query</c> with the library's <see cref="ShapeQuery"/> and
/// <see cref="QueryWorld"/>, one compact JSON object per line:
/// distance <c>{"distance","pointA","pointB"}</c>, ray <c>{"hit","shape","point","normal","fraction"}</c>,
/// cast <c>{"hit","fraction","point","normal"}</c>, overlap <c>{"shapes":[…]}</c>; a fish adds its parts.
/// </summary>
internal static class QueryAnswers
{
    /// <summary>Answers every query; the whole text, one line per query, each ending in a newline.</summary>
    /// <param name="shapes">The validated shapes.</param>
    /// <param name="queries">The validated queries.</param>
    /// <returns>The output text.</returns>
    public static string Answer(InputShape[] shapes, InputQuery[] queries)
    {
        var world = new QueryWorld();
        foreach (var s in shapes)
        {
            if (s.IsFish)
            {
                world.Add(s.Fish!);
            }
            else
            {
                world.Add(s.Shape);
            }
        }

        var found = new int[shapes.Length];
        var text = new StringBuilder();
        var buffer = new ArrayBufferWriter<byte>();
        foreach (var q in queries)
        {
            buffer.ResetWrittenCount();
            using (var w = new Utf8JsonWriter(buffer))
            {
                w.WriteStartObject();
                switch (q.Kind)
                {
                    case QueryKind.Distance:
                        WriteDistance(w, shapes[q.A], shapes[q.B]);
                        break;
                    case QueryKind.Ray:
                        WriteRay(w, world.RayCast(q.From, q.To), shapes);
                        break;
                    case QueryKind.Cast:
                        WriteCast(w, shapes[q.A], q.To, shapes[q.B]);
                        break;
                    default:
                        int n = world.Overlap(q.Box, found);
                        w.WriteStartArray("shapes");
                        foreach (int i in found.AsSpan(0, n))
                        {
                            w.WriteNumberValue(i);
                        }

                        w.WriteEndArray();
                        break;
                }

                w.WriteEndObject();
            }

            text.Append(Encoding.UTF8.GetString(buffer.WrittenSpan)).Append('\n');
        }

        return text.ToString();
    }

    private static void WriteDistance(Utf8JsonWriter w, InputShape a, InputShape b)
    {
        var r = (a.IsFish, b.IsFish) switch
        {
            (true, true) => ShapeQuery.Distance(a.Fish!, b.Fish!),
            (true, false) => ShapeQuery.Distance(a.Fish!, b.Shape),
            (false, true) => ShapeQuery.Distance(a.Shape, b.Fish!),
            _ => ShapeQuery.Distance(a.Shape, b.Shape),
        };
        w.WriteNumber("distance", OutputNumbers.Clean(r.Distance));
        Point(w, "pointA", r.PointA);
        Point(w, "pointB", r.PointB);
        Parts(w, a.IsFish || b.IsFish, r.PartA, r.PartB);
    }

    private static void WriteRay(Utf8JsonWriter w, in BodyRayHit hit, InputShape[] shapes)
    {
        w.WriteBoolean("hit", hit.Body >= 0);
        if (hit.Body < 0)
        {
            w.WriteNull("shape");
            w.WriteNull("point");
            w.WriteNull("normal");
            w.WriteNull("fraction");
            return;
        }

        w.WriteNumber("shape", hit.Body);
        Point(w, "point", hit.Result.Point);
        Point(w, "normal", hit.Result.Normal);
        w.WriteNumber("fraction", OutputNumbers.Clean(hit.Result.Fraction));
        if (shapes[hit.Body].IsFish)
        {
            w.WriteString("part", FishPartNames.OfOptional(hit.Result.Part));
        }
    }

    private static void WriteCast(Utf8JsonWriter w, InputShape a, Vector2 translation, InputShape b)
    {
        var r = (a.IsFish, b.IsFish) switch
        {
            (true, true) => ShapeQuery.Cast(a.Fish!, translation, b.Fish!),
            (true, false) => ShapeQuery.Cast(a.Fish!, translation, b.Shape),
            (false, true) => ShapeQuery.Cast(a.Shape, translation, b.Fish!),
            _ => ShapeQuery.Cast(a.Shape, translation, b.Shape),
        };
        w.WriteBoolean("hit", r.Hit);
        if (!r.Hit)
        {
            w.WriteNull("fraction");
            w.WriteNull("point");
            w.WriteNull("normal");
        }
        else
        {
            w.WriteNumber("fraction", OutputNumbers.Clean(r.Fraction));
            Point(w, "point", r.Point);
            Point(w, "normal", r.Normal);
        }

        Parts(w, a.IsFish || b.IsFish, r.PartA, r.PartB);
    }

    private static void Parts(Utf8JsonWriter w, bool withParts, FishPart? a, FishPart? b)
    {
        if (!withParts)
        {
            return;
        }

        w.WriteString("partA", FishPartNames.OfOptional(a));
        w.WriteString("partB", FishPartNames.OfOptional(b));
    }

    private static void Point(Utf8JsonWriter w, string name, Vector2 p)
    {
        w.WriteStartArray(name);
        w.WriteNumberValue(OutputNumbers.Clean(p.X));
        w.WriteNumberValue(OutputNumbers.Clean(p.Y));
        w.WriteEndArray();
    }
}
