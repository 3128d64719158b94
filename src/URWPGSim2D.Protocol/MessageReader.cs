using System.Collections.Generic;

namespace URWPGSim2D.Protocol;

/// <summary>
/// Reads protocol messages from single lines. Unknown fields are skipped; a missing field, a value
/// of the wrong type or a line that is not one JSON object throws <see cref="ProtocolException"/>
/// with a one-line message naming the field. Cycle messages are read by <see cref="CycleReader"/>.
/// </summary>
public static class MessageReader
{
    private delegate T Reading<T>(ref Utf8JsonReader r);

    /// <summary>The <c>type</c> of the message on <paramref name="line"/>.</summary>
    public static MessageType TypeOf(ReadOnlySpan<byte> line) => Read(line, TypeField);

    /// <summary>Reads a <c>hello</c>.</summary>
    public static HelloMessage ReadHello(ReadOnlySpan<byte> line) => Read(line, Hello);

    /// <summary>Reads an <c>assignment</c>.</summary>
    public static AssignmentMessage ReadAssignment(ReadOnlySpan<byte> line) => Read(line, Assignment);

    /// <summary>
    /// Reads a client's <c>decisions</c> for <paramref name="cycle"/> into <paramref name="decisions"/>
    /// (one per fish). A reported fault, a wrong count or a gear outside 0..15 is returned as that
    /// kind with a message (and <paramref name="decisions"/> may be partly written); a message for
    /// another cycle or one that is not a decisions message throws. The message's debug drawings
    /// (<c>draw</c>) go to <paramref name="drawings"/> when given (a malformed one throws), else are skipped;
    /// what the strategy printed (<c>log</c>, at most <see cref="ProtocolLimits.LogChars"/> characters kept) goes to <paramref name="log"/> when given.
    /// </summary>
    public static AnswerKind ReadDecisions(ReadOnlySpan<byte> line, int cycle, Span<Decision> decisions, out string? message, DebugRecorder? drawings = null, PrintedOutput? log = null)
    {
        message = null;
        try
        {
            var r = new Utf8JsonReader(line);
            JsonFields.StartObject(ref r);
            int? answered = null;
            int count = -1;
            AnswerKind fault = AnswerKind.Decided;
            string? bad = null;
            while (JsonFields.NextProperty(ref r))
            {
                if (r.ValueTextEquals("cycle"u8))
                {
                    answered = JsonFields.Int(ref r, "cycle");
                }
                else if (r.ValueTextEquals("decisions"u8))
                {
                    count = Decisions(ref r, decisions, ref bad);
                }
                else if (r.ValueTextEquals("fault"u8))
                {
                    string kind = JsonFields.Text(ref r, "fault") ?? "";
                    fault = kind switch
                    {
                        "exception" => AnswerKind.Exception,
                        "timeout" => AnswerKind.Timeout,
                        _ => AnswerKind.BadAnswer,
                    };
                }
                else if (r.ValueTextEquals("message"u8))
                {
                    message = JsonFields.Text(ref r, "message");
                }
                else if (drawings is not null && r.ValueTextEquals("draw"u8))
                {
                    DrawingReader.ReadArray(ref r, drawings);
                }
                else if (log is not null && r.ValueTextEquals("log"u8))
                {
                    log.Text.Append(JsonFields.Text(ref r, "log", ProtocolLimits.LogChars));
                }
                else if (log is not null && r.ValueTextEquals("logDropped"u8))
                {
                    log.Dropped = System.Math.Max(0, JsonFields.Int(ref r, "logDropped"));
                }
                else
                {
                    JsonFields.Skip(ref r);
                }
            }

            if (answered is not int c)
            {
                throw Missing("cycle");
            }

            if (c != cycle)
            {
                throw new ProtocolException($"cycle: answered cycle {c}, expected {cycle}");
            }

            if (fault != AnswerKind.Decided)
            {
                message ??= "(no message)";
                return fault;
            }

            if (bad is not null || count != decisions.Length)
            {
                message = bad ?? (count < 0 ? "decisions: missing" : $"decisions: {count} for {decisions.Length} fish");
                return AnswerKind.BadAnswer;
            }

            message = null;
            return AnswerKind.Decided;
        }
        catch (JsonException e)
        {
            throw NotJson(e);
        }
    }

    /// <summary>Reads an <c>end</c>.</summary>
    public static EndMessage ReadEnd(ReadOnlySpan<byte> line) => Read(line, End);

    /// <summary>Reads an <c>error</c>'s message.</summary>
    public static string ReadError(ReadOnlySpan<byte> line) => Read(line, Error);

    /// <summary>The most teams a match has (a four-team item).</summary>
    internal const int MaxTeams = 4;

    /// <summary>Each team's score: 2 integers, or 4 (a four-team item), into <paramref name="goals"/> (at least <see cref="MaxTeams"/> long); returns how many.</summary>
    internal static int Goals(ref Utf8JsonReader r, scoped Span<int> goals)
    {
        JsonFields.StartArray(ref r, "goals");
        int n = 0;
        while (JsonFields.NextElement(ref r, "goals"))
        {
            if (n == MaxTeams)
            {
                throw new ProtocolException($"goals: expected 2 or {MaxTeams} integers, got more");
            }

            goals[n++] = JsonFields.IntValue(ref r, "goals");
        }

        return n is 2 or MaxTeams ? n : throw new ProtocolException($"goals: expected 2 or {MaxTeams} integers, got {n}");
    }

    // Reads the one JSON object on line with read (the reader on the object's start); a line that is not JSON throws
    // ProtocolException (NotJson).
    private static T Read<T>(ReadOnlySpan<byte> line, Reading<T> read)
    {
        try
        {
            var r = new Utf8JsonReader(line);
            JsonFields.StartObject(ref r);
            return read(ref r);
        }
        catch (JsonException e)
        {
            throw NotJson(e);
        }
    }

    internal static ProtocolException NotJson(JsonException e) =>
        new($"not a JSON message (line {e.LineNumber + 1}, byte {e.BytePositionInLine + 1}): {e.Message.Split('.')[0]}");

    internal static ProtocolException Missing(string field) => new($"{field}: missing");

    private static MessageType TypeField(ref Utf8JsonReader r)
    {
        while (JsonFields.NextProperty(ref r))
        {
            if (!r.ValueTextEquals("type"u8))
            {
                JsonFields.Skip(ref r);
                continue;
            }

            r.Read();
            if (r.TokenType != JsonTokenType.String)
            {
                throw new ProtocolException($"type: expected a string, got {JsonFields.Describe(ref r)}");
            }

            return r.ValueTextEquals("hello"u8) ? MessageType.Hello
                : r.ValueTextEquals("assignment"u8) ? MessageType.Assignment
                : r.ValueTextEquals("cycle"u8) ? MessageType.Cycle
                : r.ValueTextEquals("decisions"u8) ? MessageType.Decisions
                : r.ValueTextEquals("end"u8) ? MessageType.End
                : r.ValueTextEquals("error"u8) ? MessageType.Error
                : MessageType.Unknown;
        }

        return MessageType.Unknown;
    }

    private static HelloMessage Hello(ref Utf8JsonReader r)
    {
        int? version = null;
        string? token = null;
        string? name = null;
        bool packed = false, series = false;
        while (JsonFields.NextProperty(ref r))
        {
            if (r.ValueTextEquals("version"u8))
            {
                version = JsonFields.Int(ref r, "version");
            }
            else if (r.ValueTextEquals("packed"u8))
            {
                packed = JsonFields.Bool(ref r, "packed");
            }
            else if (r.ValueTextEquals("series"u8))
            {
                series = JsonFields.Bool(ref r, "series");
            }
            else if (r.ValueTextEquals("token"u8))
            {
                token = JsonFields.Text(ref r, "token");
            }
            else if (r.ValueTextEquals("name"u8))
            {
                name = JsonFields.Text(ref r, "name");
            }
            else
            {
                JsonFields.Skip(ref r);
            }
        }

        return new HelloMessage(version ?? throw Missing("version"), token, name) { Packed = packed, Series = series };
    }

    private static AssignmentMessage Assignment(ref Utf8JsonReader r)
    {
        int? version = null, team = null, fishCount = null, ballCount = null, totalCycles = null, deadline = null;
        string item = "", itemName = "match";
        int[]? fish = null;
        float? length = null, width = null;
        ObstacleView[] obstacles = [];
        bool draw = false, log = false, packed = false, series = false;
        while (JsonFields.NextProperty(ref r))
        {
            if (r.ValueTextEquals("version"u8))
            {
                version = JsonFields.Int(ref r, "version");
            }
            else if (r.ValueTextEquals("team"u8))
            {
                team = JsonFields.Int(ref r, "team");
            }
            else if (r.ValueTextEquals("item"u8))
            {
                item = JsonFields.Text(ref r, "item") ?? "";
            }
            else if (r.ValueTextEquals("itemName"u8))
            {
                itemName = JsonFields.Text(ref r, "itemName") ?? "match";
            }
            else if (r.ValueTextEquals("fish"u8))
            {
                fish = Ints(ref r, "fish");
            }
            else if (r.ValueTextEquals("fishCount"u8))
            {
                fishCount = JsonFields.Int(ref r, "fishCount");
            }
            else if (r.ValueTextEquals("ballCount"u8))
            {
                ballCount = JsonFields.Int(ref r, "ballCount");
            }
            else if (r.ValueTextEquals("totalCycles"u8))
            {
                totalCycles = JsonFields.Int(ref r, "totalCycles");
            }
            else if (r.ValueTextEquals("deadlineMs"u8))
            {
                deadline = JsonFields.Int(ref r, "deadlineMs");
            }
            else if (r.ValueTextEquals("field"u8))
            {
                (length, width) = Field(ref r);
            }
            else if (r.ValueTextEquals("obstacles"u8))
            {
                obstacles = Obstacles(ref r);
            }
            else if (r.ValueTextEquals("draw"u8))
            {
                draw = JsonFields.Bool(ref r, "draw");
            }
            else if (r.ValueTextEquals("log"u8))
            {
                log = JsonFields.Bool(ref r, "log");
            }
            else if (r.ValueTextEquals("packed"u8))
            {
                packed = JsonFields.Bool(ref r, "packed");
            }
            else if (r.ValueTextEquals("series"u8))
            {
                series = JsonFields.Bool(ref r, "series");
            }
            else
            {
                JsonFields.Skip(ref r);
            }
        }

        var a = new AssignmentMessage(
            version ?? throw Missing("version"), team ?? throw Missing("team"), item, itemName, fish ?? throw Missing("fish"),
            fishCount ?? throw Missing("fishCount"), ballCount ?? throw Missing("ballCount"), totalCycles ?? 0,
            deadline ?? throw Missing("deadlineMs"), length ?? throw Missing("field.length"), width ?? throw Missing("field.width"), obstacles)
        {
            Draw = draw,
            Log = log,
            Packed = packed,
            Series = series,
        };
        Check(a);
        return a;
    }

    private static EndMessage End(ref Utf8JsonReader r)
    {
        int cycle = 0, faults = 0;
        Span<int> goals = stackalloc int[MaxTeams];
        int teams = 2;
        while (JsonFields.NextProperty(ref r))
        {
            if (r.ValueTextEquals("cycle"u8))
            {
                cycle = JsonFields.Int(ref r, "cycle");
            }
            else if (r.ValueTextEquals("faults"u8))
            {
                faults = JsonFields.Int(ref r, "faults");
            }
            else if (r.ValueTextEquals("goals"u8))
            {
                teams = Goals(ref r, goals);
            }
            else
            {
                JsonFields.Skip(ref r);
            }
        }

        return new EndMessage(cycle, goals[..teams].ToArray(), faults);
    }

    private static string Error(ref Utf8JsonReader r)
    {
        string? message = null;
        while (JsonFields.NextProperty(ref r))
        {
            if (r.ValueTextEquals("message"u8))
            {
                message = JsonFields.Text(ref r, "message");
            }
            else
            {
                JsonFields.Skip(ref r);
            }
        }

        return message ?? "(no message)";
    }

    // The decisions array: writes up to decisions.Length entries, returns how many there were; the
    // first unusable entry goes to bad.
    private static int Decisions(ref Utf8JsonReader r, Span<Decision> decisions, ref string? bad)
    {
        JsonFields.StartArray(ref r, "decisions");
        int n = 0;
        while (JsonFields.NextElement(ref r, "decisions"))
        {
            if (r.TokenType != JsonTokenType.StartArray)
            {
                bad ??= $"decisions[{n}]: expected [vcode, tcode], got {JsonFields.Describe(ref r)}";
                r.Skip();
                n++;
                continue;
            }

            int v = -1, t = -1, k = 0;
            while (JsonFields.NextElement(ref r, "decisions"))
            {
                if (r.TokenType == JsonTokenType.Number && r.TryGetInt32(out int gear) && gear is >= 0 and <= 15)
                {
                    if (k == 0)
                    {
                        v = gear;
                    }
                    else if (k == 1)
                    {
                        t = gear;
                    }
                }
                else
                {
                    bad ??= $"decisions[{n}][{k}]: expected a gear 0..15, got {JsonFields.Describe(ref r)}";
                    r.Skip();
                }

                k++;
            }

            if (k != 2)
            {
                bad ??= $"decisions[{n}]: expected [vcode, tcode], got {k} values";
            }
            else if (v >= 0 && t >= 0 && n < decisions.Length)
            {
                decisions[n] = new Decision(v, t);
            }

            n++;
        }

        return n;
    }

    private static int[] Ints(ref Utf8JsonReader r, string field)
    {
        JsonFields.StartArray(ref r, field);
        var list = new List<int>();
        while (JsonFields.NextElement(ref r, field))
        {
            list.Add(JsonFields.IntValue(ref r, field));
        }

        return list.ToArray();
    }

    private static (float Length, float Width) Field(ref Utf8JsonReader r)
    {
        JsonFields.StartObjectValue(ref r, "field");
        float? length = null, width = null;
        while (JsonFields.NextProperty(ref r))
        {
            if (r.ValueTextEquals("length"u8))
            {
                length = JsonFields.Float(ref r, "field.length");
            }
            else if (r.ValueTextEquals("width"u8))
            {
                width = JsonFields.Float(ref r, "field.width");
            }
            else
            {
                JsonFields.Skip(ref r);
            }
        }

        return (length ?? throw Missing("field.length"), width ?? throw Missing("field.width"));
    }

    private static ObstacleView[] Obstacles(ref Utf8JsonReader r)
    {
        JsonFields.StartArray(ref r, "obstacles");
        var list = new List<ObstacleView>();
        while (JsonFields.NextObject(ref r, "obstacles", list.Count))
        {
            int? index = null;
            ObstacleKind? kind = null;
            System.Numerics.Vector2? center = null;
            float length = 0, width = 0, heading = 0, radius = 0;
            while (JsonFields.NextProperty(ref r))
            {
                if (r.ValueTextEquals("index"u8))
                {
                    index = JsonFields.Int(ref r, "obstacles.index");
                }
                else if (r.ValueTextEquals("kind"u8))
                {
                    kind = JsonFields.Text(ref r, "obstacles.kind") switch
                    {
                        "round" => ObstacleKind.Round,
                        "rectangle" => ObstacleKind.Rectangle,
                        var other => throw new ProtocolException($"obstacles.kind: expected round or rectangle, got {other}"),
                    };
                }
                else if (r.ValueTextEquals("center"u8))
                {
                    center = JsonFields.Vector(ref r, "obstacles.center");
                }
                else if (r.ValueTextEquals("length"u8))
                {
                    length = JsonFields.Float(ref r, "obstacles.length");
                }
                else if (r.ValueTextEquals("width"u8))
                {
                    width = JsonFields.Float(ref r, "obstacles.width");
                }
                else if (r.ValueTextEquals("heading"u8))
                {
                    heading = JsonFields.Float(ref r, "obstacles.heading");
                }
                else if (r.ValueTextEquals("radius"u8))
                {
                    radius = JsonFields.Float(ref r, "obstacles.radius");
                }
                else
                {
                    JsonFields.Skip(ref r);
                }
            }

            list.Add(new ObstacleView(
                index ?? throw Missing("obstacles.index"), kind ?? throw Missing("obstacles.kind"), center ?? throw Missing("obstacles.center"),
                length, width, heading, radius));
        }

        return list.ToArray();
    }

    private static void Check(AssignmentMessage a)
    {
        if (a.Team is < 0 or >= MaxTeams)
        {
            throw new ProtocolException($"team: {a.Team} is not 0 to {MaxTeams - 1}");
        }

        if (a.FishCount < 0 || a.BallCount < 0)
        {
            throw new ProtocolException($"fishCount/ballCount: {a.FishCount}/{a.BallCount} is negative");
        }

        foreach (int f in a.Fish)
        {
            if (f < 0 || f >= a.FishCount)
            {
                throw new ProtocolException($"fish: {f} is not a fish index below fishCount {a.FishCount}");
            }
        }
    }
}
