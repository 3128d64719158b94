using System.Buffers;

namespace URWPGSim2D.Protocol;

/// <summary>
/// Writes protocol messages as single JSON lines (ending in <c>\n</c>) into a reused buffer; the
/// span a method returns is valid until the next call. Numbers are written in their shortest form
/// that reads back to the same <see cref="float"/>, so a snapshot crosses the protocol bit for bit;
/// a number that is not finite is written as <c>null</c>. A cycle message allocates nothing once
/// the buffer has grown.
/// </summary>
public sealed class MessageWriter
{
    private readonly ArrayBufferWriter<byte> _buffer = new(4096);
    private readonly Utf8JsonWriter _json;
    private byte[] _packed = [];

    /// <summary>Creates a writer.</summary>
    public MessageWriter()
    {
        _json = new Utf8JsonWriter(_buffer, new JsonWriterOptions { SkipValidation = true });
    }

    /// <summary>
    /// A client's <c>hello</c>; <paramref name="packed"/>: the client reads packed cycles (<see cref="PackedCycle"/>);
    /// <paramref name="series"/>: the client can play several matches on the connection (<see cref="HelloMessage.Series"/>).
    /// </summary>
    public ReadOnlySpan<byte> Hello(int version, string? token, string? name, bool packed = false, bool series = false)
    {
        Begin("hello");
        _json.WriteNumber("version", version);
        if (packed)
        {
            _json.WriteBoolean("packed", true);
        }

        if (series)
        {
            _json.WriteBoolean("series", true);
        }

        WriteOptional("token", token);
        WriteOptional("name", name);
        return End();
    }

    /// <summary>The server's <c>assignment</c>.</summary>
    public ReadOnlySpan<byte> Assignment(AssignmentMessage a)
    {
        ArgumentNullException.ThrowIfNull(a);
        Begin("assignment");
        _json.WriteNumber("version", a.Version);
        _json.WriteNumber("team", a.Team);
        _json.WriteString("item", a.Item);
        _json.WriteString("itemName", a.ItemName);
        Ints("fish", a.Fish);
        _json.WriteNumber("fishCount", a.FishCount);
        _json.WriteNumber("ballCount", a.BallCount);
        _json.WriteNumber("totalCycles", a.TotalCycles);
        _json.WriteNumber("cycleMs", 100);
        _json.WriteNumber("deadlineMs", a.DeadlineMs);
        if (a.Draw)
        {
            _json.WriteBoolean("draw", true);
        }

        if (a.Log)
        {
            _json.WriteBoolean("log", true);
        }

        if (a.Packed)
        {
            _json.WriteBoolean("packed", true);
        }

        if (a.Series)
        {
            _json.WriteBoolean("series", true);
        }

        _json.WriteStartObject("field");
        Number("length", a.FieldLength);
        Number("width", a.FieldWidth);
        Number("goalWidth", 400f);
        Number("goalDepth", 150f);
        _json.WriteEndObject();
        _json.WriteStartArray("obstacles");
        foreach (var o in a.Obstacles)
        {
            _json.WriteStartObject();
            _json.WriteNumber("index", o.Index);
            _json.WriteString("kind", o.Kind == ObstacleKind.Round ? "round" : "rectangle");
            Vector("center", o.Center);
            Number("length", o.Length);
            Number("width", o.Width);
            Number("heading", o.Heading);
            Number("radius", o.Radius);
            _json.WriteEndObject();
        }

        _json.WriteEndArray();
        return End();
    }

    /// <summary>
    /// The server's <c>cycle</c>: everything of <paramref name="s"/> that changes during a match; with
    /// <paramref name="packed"/>, the fish and balls as one <c>packed</c> field (<see cref="PackedCycle"/>) instead of <c>fish</c> and <c>balls</c>.
    /// </summary>
    public ReadOnlySpan<byte> Cycle(MatchSnapshot s, bool packed = false)
    {
        ArgumentNullException.ThrowIfNull(s);
        Begin("cycle");
        _json.WriteNumber("cycle", s.Cycle);
        _json.WriteStartArray("goals");
        for (int t = 0; t < s.TeamCount; t++)
        {
            _json.WriteNumberValue(s.GoalsOf(t));
        }

        _json.WriteEndArray();
        _json.WriteBoolean("sidesSwapped", s.SidesSwapped);
        _json.WriteStartObject("variables");
        if (s.Variables is OrderedVariables ordered)
        {
            foreach (var pair in ordered) // its own enumerator: no allocation a cycle
            {
                _json.WriteString(pair.Key, pair.Value);
            }
        }
        else if (s.Variables.Count > 0)
        {
            foreach (var pair in s.Variables)
            {
                _json.WriteString(pair.Key, pair.Value);
            }
        }

        _json.WriteEndObject();
        if (packed)
        {
            // The base64 text goes in as it is, quotes included (the writer's own base64 allocates a cycle, and its strings escape '+').
            int length = PackedCycle.Length(s.Fish.Length, s.Balls.Length);
            int text = System.Buffers.Text.Base64.GetMaxEncodedToUtf8Length(length);
            if (_packed.Length < length + text + 2)
            {
                _packed = new byte[length + text + 2];
            }

            var bytes = _packed.AsSpan(0, length);
            var quoted = _packed.AsSpan(length);
            PackedCycle.Write(s, bytes);
            System.Buffers.Text.Base64.EncodeToUtf8(bytes, quoted[1..], out _, out int written);
            quoted[0] = (byte)'"';
            quoted[written + 1] = (byte)'"';
            _json.WritePropertyName("packed"u8);
            _json.WriteRawValue(quoted[..(written + 2)], skipInputValidation: true);
            return End();
        }

        _json.WriteStartArray("fish");
        foreach (ref readonly var f in s.Fish)
        {
            _json.WriteStartObject();
            _json.WriteNumber("index", f.Index);
            _json.WriteNumber("team", f.Team);
            Vector("position", f.Position);
            Number("heading", f.Heading);
            Number("speed", f.Speed);
            Number("angularSpeed", f.AngularSpeed);
            Number("bodyLength", f.BodyLength);
            Number("headLength", f.HeadLength);
            Number("width", f.Width);
            Triple("joints", f.Joint1, f.Joint2, f.Joint3);
            Triple("tailLengths", f.TailLength1, f.TailLength2, f.TailLength3);
            _json.WriteStartArray("decision");
            _json.WriteNumberValue(f.Decision.VCode);
            _json.WriteNumberValue(f.Decision.TCode);
            _json.WriteEndArray();
            _json.WriteEndObject();
        }

        _json.WriteEndArray();
        _json.WriteStartArray("balls");
        foreach (ref readonly var b in s.Balls)
        {
            _json.WriteStartObject();
            _json.WriteNumber("index", b.Index);
            Vector("position", b.Position);
            Vector("velocity", b.Velocity);
            Number("radius", b.Radius);
            _json.WriteEndObject();
        }

        _json.WriteEndArray();
        return End();
    }

    /// <summary>A client's <c>decisions</c> for <paramref name="cycle"/>: one <c>[vcode, tcode]</c> per fish, and the strategy's debug drawings when given and not empty.</summary>
    public ReadOnlySpan<byte> Decisions(int cycle, ReadOnlySpan<Decision> decisions, DebugRecorder? drawings = null, string? log = null, int logDropped = 0)
    {
        Begin("decisions");
        _json.WriteNumber("cycle", cycle);
        _json.WriteStartArray("decisions");
        foreach (var d in decisions)
        {
            _json.WriteStartArray();
            _json.WriteNumberValue(d.VCode);
            _json.WriteNumberValue(d.TCode);
            _json.WriteEndArray();
        }

        _json.WriteEndArray();
        Drawings(drawings, log, logDropped);
        return End();
    }

    /// <summary>A client's <c>decisions</c> for <paramref name="cycle"/> reporting a fault instead (the fish keep their last decisions).</summary>
    public ReadOnlySpan<byte> Fault(int cycle, AnswerKind fault, string message, DebugRecorder? drawings = null, string? log = null, int logDropped = 0)
    {
        Begin("decisions");
        _json.WriteNumber("cycle", cycle);
        _json.WriteString("fault", fault switch
        {
            AnswerKind.Exception => "exception",
            AnswerKind.Timeout => "timeout",
            AnswerKind.BadAnswer => "badAnswer",
            _ => throw new ArgumentOutOfRangeException(nameof(fault), fault, "a fault is exception, timeout or badAnswer"),
        });
        _json.WriteString("message", Cut(message));
        Drawings(drawings, log, logDropped);
        return End();
    }

    private void Drawings(DebugRecorder? drawings, string? log, int logDropped)
    {
        if (drawings is { Count: > 0 })
        {
            DebugShapeJson.WriteArray(_json, drawings);
        }

        if (!string.IsNullOrEmpty(log))
        {
            _json.WriteString("log", log.Length <= ProtocolLimits.LogChars ? log : log[..ProtocolLimits.LogChars]);
        }

        if (logDropped > 0)
        {
            _json.WriteNumber("logDropped", logDropped);
        }
    }

    /// <summary>The server's <c>end</c>.</summary>
    public ReadOnlySpan<byte> End(EndMessage end)
    {
        ArgumentNullException.ThrowIfNull(end);
        Begin("end");
        _json.WriteNumber("cycle", end.Cycle);
        Ints("goals", end.Goals);
        _json.WriteNumber("faults", end.Faults);
        return End();
    }

    /// <summary>The server's <c>error</c> (the connection is closed after it).</summary>
    public ReadOnlySpan<byte> Error(string message)
    {
        Begin("error");
        _json.WriteString("message", Cut(message));
        return End();
    }

    private static string Cut(string text) => text.Length <= ProtocolLimits.TextChars ? text : text[..ProtocolLimits.TextChars];

    private void Begin(string type)
    {
        _buffer.ResetWrittenCount();
        _json.Reset(_buffer);
        _json.WriteStartObject();
        _json.WriteString("type", type);
    }

    private ReadOnlySpan<byte> End()
    {
        _json.WriteEndObject();
        _json.Flush();
        _buffer.GetSpan(1)[0] = (byte)'\n';
        _buffer.Advance(1);
        return _buffer.WrittenSpan;
    }

    private void Ints(string name, ReadOnlySpan<int> values)
    {
        _json.WriteStartArray(name);
        foreach (int v in values)
        {
            _json.WriteNumberValue(v);
        }

        _json.WriteEndArray();
    }

    private void WriteOptional(string name, string? value)
    {
        if (value is not null)
        {
            _json.WriteString(name, Cut(value));
        }
    }

    private void Number(string name, float value)
    {
        _json.WritePropertyName(name);
        NumberValue(value);
    }

    private void NumberValue(float value)
    {
        if (float.IsFinite(value))
        {
            _json.WriteNumberValue(value);
        }
        else
        {
            _json.WriteNullValue();
        }
    }

    private void Vector(string name, Vector2 v)
    {
        _json.WriteStartArray(name);
        NumberValue(v.X);
        NumberValue(v.Y);
        _json.WriteEndArray();
    }

    private void Triple(string name, float a, float b, float c)
    {
        _json.WriteStartArray(name);
        NumberValue(a);
        NumberValue(b);
        NumberValue(c);
        _json.WriteEndArray();
    }
}
