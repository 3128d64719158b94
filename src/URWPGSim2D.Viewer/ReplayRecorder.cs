using System.Buffers;
using System.IO;
using System.Runtime.InteropServices;
using System.Text.Json;

namespace URWPGSim2D.Viewer;

/// <summary>
/// Collects trace lines (the bytes <c>TraceLine</c> writes, or the lines of a trace file) and packs
/// them into the replay page's data: the cycle-0 layout as JSON, every fish pose and ball position
/// as 16-bit integers (positions in steps of <see cref="PositionStep"/> mm, angles in steps of
/// 10⁻⁴ rad), the contacts' action points and normals the same way, the score changes and the
/// events, and what a body's details show (<see cref="ReplayDetails"/>) — all base64 inside one JSON object (docs/viewer.md, "The replay page's data").
/// </summary>
public sealed class ReplayRecorder : Engine.Trace.ITraceSink
{
    /// <summary>Angle step of the packed data, rad.</summary>
    public const double AngleStep = 1e-4;

    private const int FishValues = 6, BallValues = 2, ContactValues = 4;

    private readonly List<short> _frames = new(1 << 16);
    private readonly List<ushort> _contactCounts = new(1 << 12);
    private readonly List<short> _contacts = new(1 << 12);
    private readonly ArrayBufferWriter<byte> _scores = new(1 << 10);
    private readonly ArrayBufferWriter<byte> _events = new(1 << 10);
    private readonly ArrayBufferWriter<byte> _draws = new(1 << 10);
    private readonly ArrayBufferWriter<byte> _logs = new(1 << 10);
    private readonly ReplayDetails _details = new();
    private Utf8JsonWriter? _drawJson;
    private Utf8JsonWriter? _logJson;
    private readonly Utf8JsonWriter _scoreJson;
    private readonly Utf8JsonWriter _eventJson;
    private double[] _lastScore = [];
    private string? _layout;
    private string _item = "default";
    private int _firstCycle;
    private int _fish;
    private int _balls;

    /// <summary>Creates an empty recorder.</summary>
    public ReplayRecorder()
    {
        _scoreJson = new Utf8JsonWriter(_scores);
        _eventJson = new Utf8JsonWriter(_events);
        _scoreJson.WriteStartArray();
        _eventJson.WriteStartArray();
    }

    /// <summary>Lines added so far.</summary>
    public int Count { get; private set; }

    /// <summary>Position step of the packed data, mm (0.1 for the usual pools; coarser for pools over 4 m).</summary>
    public double PositionStep { get; private set; } = 0.1;

    /// <summary>Adds one trace line.</summary>
    /// <exception cref="TraceFormatException">The line is not a cycle line the viewer can use.</exception>
    public void Add(ReadOnlySpan<byte> line)
    {
        JsonDocument document;
        try
        {
            document = JsonDocument.Parse(line.ToArray());
        }
        catch (JsonException e)
        {
            throw new TraceFormatException($"not JSON ({e.Message})");
        }

        using (document)
        {
            Add(document.RootElement);
        }
    }

    /// <inheritdoc/>
    void Engine.Trace.ITraceSink.WriteLine(ReadOnlySpan<byte> line) => Add(line);

    /// <summary>Adds one parsed trace line.</summary>
    /// <exception cref="TraceFormatException">The line is not a cycle line the viewer can use.</exception>
    public void Add(JsonElement line)
    {
        if (line.ValueKind != JsonValueKind.Object)
        {
            throw new TraceFormatException("a line must be a JSON object");
        }

        int cycle = Int(line, "cycle");
        if (Count == 0)
        {
            Start(line, cycle);
        }
        else if (cycle != _firstCycle + Count)
        {
            throw new TraceFormatException($"cycle: expected {_firstCycle + Count} (lines must be consecutive cycles), got {cycle}");
        }

        var fish = Array(line, "fish");
        if (fish.GetArrayLength() != _fish)
        {
            throw new TraceFormatException($"fish: {fish.GetArrayLength()} fish, the layout has {_fish}");
        }

        int i = 0;
        foreach (var f in fish.EnumerateArray())
        {
            string at = $"fish[{i++}]";
            var (x, z) = Point(f, "position", at);
            Add(Position(x));
            Add(Position(z));
            Add(Angle(Wrap(Number(f, "heading", at))));
            var joints = Array(f, "joints", at);
            if (joints.GetArrayLength() != 3)
            {
                throw new TraceFormatException($"{at}.joints: expected 3 angles, got {joints.GetArrayLength()}");
            }

            foreach (var j in joints.EnumerateArray())
            {
                Add(Angle(Value(j, at + ".joints")));
            }

            _details.AddFish(f, PositionStep, AngleStep);
        }

        var balls = Array(line, "balls");
        if (balls.GetArrayLength() != _balls)
        {
            throw new TraceFormatException($"balls: {balls.GetArrayLength()} balls, the layout has {_balls}");
        }

        i = 0;
        foreach (var b in balls.EnumerateArray())
        {
            var (x, z) = Point(b, "position", $"balls[{i++}]");
            Add(Position(x));
            Add(Position(z));
            _details.AddBall(b, PositionStep);
        }

        int contacts = 0;
        if (line.TryGetProperty("contacts", out var list) && list.ValueKind == JsonValueKind.Array)
        {
            foreach (var c in list.EnumerateArray())
            {
                string at = $"contacts[{contacts}]";
                var (px, pz) = Point(c, "actionPoint", at);
                var (nx, nz) = Point(c, "normal", at);
                _contacts.Add(Position(px));
                _contacts.Add(Position(pz));
                _contacts.Add(Angle(nx));
                _contacts.Add(Angle(nz));
                _details.AddContact(c);
                contacts++;
            }
        }

        _contactCounts.Add((ushort)Math.Min(contacts, ushort.MaxValue));
        AddScore(line, cycle);
        AddEvents(line, cycle);
        PerCycle(line, cycle, "draw", "a drawing", _draws, ref _drawJson);
        PerCycle(line, cycle, "log", "a strategy's output", _logs, ref _logJson);
        Count++;
    }

    /// <summary>The page data: one JSON object (no '&lt;' anywhere, so it is safe inside a script element).</summary>
    public string ToJson()
    {
        if (Count == 0 || _layout is null)
        {
            throw new InvalidOperationException("no cycle line was added");
        }

        _scoreJson.WriteEndArray();
        _scoreJson.Flush();
        _eventJson.WriteEndArray();
        _eventJson.Flush();
        var s = new StringBuilder(((_frames.Count + _contacts.Count) * 3) + 4096);
        s.Append("{\"version\":1,\"item\":").Append(JsonSerializer.Serialize(_item, ViewerJsonContext.Default.String))
            .Append(",\"layout\":").Append(_layout)
            .Append(CultureInfo.InvariantCulture, $",\"firstCycle\":{_firstCycle},\"cycles\":{Count},\"q\":{PositionStep.ToString("R", CultureInfo.InvariantCulture)},\"angle\":{AngleStep.ToString("R", CultureInfo.InvariantCulture)}")
            .Append(",\"frames\":\"").Append(Convert.ToBase64String(MemoryMarshal.AsBytes(CollectionsMarshal.AsSpan(_frames))))
            .Append("\",\"contactCounts\":\"").Append(Convert.ToBase64String(MemoryMarshal.AsBytes(CollectionsMarshal.AsSpan(_contactCounts))))
            .Append("\",\"contacts\":\"").Append(Convert.ToBase64String(MemoryMarshal.AsBytes(CollectionsMarshal.AsSpan(_contacts))))
            .Append("\",\"scores\":").Append(Encoding.UTF8.GetString(_scores.WrittenSpan))
            .Append(",\"events\":").Append(Encoding.UTF8.GetString(_events.WrittenSpan));
        _details.Finish(s);
        Finish(s, "draws", _draws, _drawJson);
        Finish(s, "logs", _logs, _logJson);

        s.Append('}');
        return s.Replace("<", "\\u003c").ToString();
    }

    // The cycle-0 line: item, layout, counts and the position step.
    private void Start(JsonElement line, int cycle)
    {
        if (!line.TryGetProperty("layout", out var layout) || layout.ValueKind != JsonValueKind.Object)
        {
            throw new TraceFormatException("layout: missing on the first line (a trace from an older version? play the match again with run --trace)");
        }

        _firstCycle = cycle;
        _item = line.TryGetProperty("item", out var item) && item.ValueKind == JsonValueKind.String ? item.GetString()! : "default";
        var field = Object(layout, "field", "layout");
        double half = Math.Max(Number(field, "length", "layout.field"), Number(field, "width", "layout.field")) / 2;
        if (!(half > 0))
        {
            throw new TraceFormatException($"layout.field: the pool must have a positive size, got half extent {half}");
        }

        while (PositionStep * short.MaxValue < 1.5 * half)
        {
            PositionStep *= 2;
        }

        _fish = Array(layout, "fish", "layout").GetArrayLength();
        _balls = Array(layout, "balls", "layout").GetArrayLength();
        int i = 0;
        foreach (var f in Array(layout, "fish", "layout").EnumerateArray())
        {
            string at = $"layout.fish[{i++}]";
            Int(f, "team", at);
            var size = Object(f, "size", at);
            foreach (var name in (string[])["length", "width", "head"])
            {
                if (!(Number(size, name, at + ".size") > 0))
                {
                    throw new TraceFormatException($"{at}.size.{name}: must be > 0");
                }
            }

            if (Array(size, "joints", at + ".size").GetArrayLength() != 3)
            {
                throw new TraceFormatException($"{at}.size.joints: expected 3 lengths");
            }
        }

        i = 0;
        foreach (var b in Array(layout, "balls", "layout").EnumerateArray())
        {
            Number(b, "radius", $"layout.balls[{i++}]");
        }

        foreach (var name in (string[])["goals", "goalBlocks", "obstacles", "zones", "teams"])
        {
            Array(layout, name, "layout");
        }

        var buffer = new ArrayBufferWriter<byte>(1 << 12);
        using (var w = new Utf8JsonWriter(buffer))
        {
            layout.WriteTo(w);
        }

        _layout = Encoding.UTF8.GetString(buffer.WrittenSpan);
    }

    private void AddScore(JsonElement line, int cycle)
    {
        if (!line.TryGetProperty("score", out var score) || score.ValueKind != JsonValueKind.Array)
        {
            if (Count == 0)
            {
                _lastScore = [0, 0];
                WriteScore(cycle);
            }

            return;
        }

        var values = new double[Math.Max(2, score.GetArrayLength())];
        int t = 0;
        foreach (var v in score.EnumerateArray())
        {
            values[t++] = Value(v, "score");
        }

        if (Count > 0 && values.AsSpan().SequenceEqual(_lastScore))
        {
            return;
        }

        _lastScore = values;
        WriteScore(cycle);
    }

    private void WriteScore(int cycle)
    {
        _scoreJson.WriteStartArray();
        _scoreJson.WriteNumberValue(cycle);
        foreach (double v in _lastScore)
        {
            _scoreJson.WriteNumberValue(v);
        }

        _scoreJson.WriteEndArray();
    }

    private void AddEvents(JsonElement line, int cycle)
    {
        if (!line.TryGetProperty("events", out var events) || events.ValueKind != JsonValueKind.Array)
        {
            return;
        }

        int i = 0;
        foreach (var e in events.EnumerateArray())
        {
            if (e.ValueKind != JsonValueKind.Object || !e.TryGetProperty("kind", out var kind) || kind.ValueKind != JsonValueKind.String)
            {
                throw new TraceFormatException($"events[{i}]: an event is an object with a \"kind\" string");
            }

            _eventJson.WriteStartObject();
            _eventJson.WriteNumber("cycle", cycle);
            foreach (var p in e.EnumerateObject())
            {
                if (p.Name != "cycle")
                {
                    p.WriteTo(_eventJson);
                }
            }

            _eventJson.WriteEndObject();
            i++;
        }
    }

    // The strategies' debug drawings (draw, run --debug-draw) and output (log, run --strategy-log):
    // [cycle, [entry, ...]] for each line that has any, the entries as in the trace.
    private static void PerCycle(JsonElement line, int cycle, string name, string what, ArrayBufferWriter<byte> buffer, ref Utf8JsonWriter? json)
    {
        if (!line.TryGetProperty(name, out var entries))
        {
            return;
        }

        if (entries.ValueKind != JsonValueKind.Array)
        {
            throw new TraceFormatException($"{name}: expected an array");
        }

        if (json is null)
        {
            json = new Utf8JsonWriter(buffer);
            json.WriteStartArray();
        }

        json.WriteStartArray();
        json.WriteNumberValue(cycle);
        json.WriteStartArray();
        int i = 0;
        foreach (var entry in entries.EnumerateArray())
        {
            if (entry.ValueKind != JsonValueKind.Object || !entry.TryGetProperty(name == "draw" ? "kind" : "text", out var key) || key.ValueKind != JsonValueKind.String)
            {
                throw new TraceFormatException($"{name}[{i}]: {what} is an object with a \"{(name == "draw" ? "kind" : "text")}\" string");
            }

            entry.WriteTo(json);
            i++;
        }

        json.WriteEndArray();
        json.WriteEndArray();
    }

    // Appends ,"name":[...] when the match had any.
    private static void Finish(StringBuilder s, string name, ArrayBufferWriter<byte> buffer, Utf8JsonWriter? json)
    {
        if (json is null)
        {
            return;
        }

        json.WriteEndArray();
        json.Flush();
        s.Append(",\"").Append(name).Append("\":").Append(Encoding.UTF8.GetString(buffer.WrittenSpan));
    }

    private void Add(short value) => _frames.Add(value);

    private short Position(double mm) => Quantise(mm / PositionStep);

    private static short Angle(double rad) => Quantise(rad / AngleStep);

    private static short Quantise(double v) => (short)Math.Clamp(Math.Round(v), -short.MaxValue, short.MaxValue);

    private static double Wrap(double angle) => angle - (2 * Math.PI * Math.Round(angle / (2 * Math.PI)));

    private static JsonElement Member(JsonElement o, string name, string at, JsonValueKind kind, string what)
    {
        string where = at.Length == 0 ? name : $"{at}.{name}";
        if (!o.TryGetProperty(name, out var v))
        {
            throw new TraceFormatException($"{where}: missing");
        }

        return v.ValueKind == kind ? v : throw new TraceFormatException($"{where}: expected {what}, got {v.ValueKind.ToString().ToLowerInvariant()}");
    }

    private static JsonElement Array(JsonElement o, string name, string at = "") => Member(o, name, at, JsonValueKind.Array, "an array");

    private static JsonElement Object(JsonElement o, string name, string at) => Member(o, name, at, JsonValueKind.Object, "an object");

    private static double Number(JsonElement o, string name, string at = "") => Value(Member(o, name, at, JsonValueKind.Number, "a number"), at.Length == 0 ? name : $"{at}.{name}");

    private static int Int(JsonElement o, string name, string at = "")
    {
        var v = Member(o, name, at, JsonValueKind.Number, "an integer");
        return v.TryGetInt32(out int n) ? n : throw new TraceFormatException($"{(at.Length == 0 ? name : $"{at}.{name}")}: expected an integer, got {v.GetRawText()}");
    }

    private static double Value(JsonElement v, string at)
    {
        if (v.ValueKind != JsonValueKind.Number || !double.IsFinite(v.GetDouble()))
        {
            throw new TraceFormatException($"{at}: expected a finite number, got {v.GetRawText()}");
        }

        return v.GetDouble();
    }

    private static (double X, double Z) Point(JsonElement o, string name, string at)
    {
        var p = Array(o, name, at);
        if (p.GetArrayLength() != 2)
        {
            throw new TraceFormatException($"{at}.{name}: expected [x, z]");
        }

        return (Value(p[0], $"{at}.{name}[0]"), Value(p[1], $"{at}.{name}[1]"));
    }
}
