using System.Runtime.InteropServices;
using System.Text.Json;

namespace URWPGSim2D.Viewer;

/// <summary>
/// The replay page's data for inspecting one body (docs/viewer.md, "Fish details"): per cycle each
/// fish's speed and angular speed, each ball's velocity (16-bit integers in the frames' steps), each
/// fish's decision and gear codes (bytes, 255 where the line has none), and which bodies and parts
/// each contact joined (an index per contact into a table of the distinct [a, b, partA, partB]).
/// Filled by <see cref="ReplayRecorder"/> line by line.
/// </summary>
internal sealed class ReplayDetails
{
    /// <summary>A byte of <c>decisions</c> where the trace line has no decision (cycle 0, older traces).</summary>
    public const byte None = 255;

    private readonly List<short> _motion = new(1 << 14);
    private readonly List<byte> _decisions = new(1 << 12);
    private readonly List<ushort> _contactKinds = new(1 << 12);
    private readonly Dictionary<(string A, string B, string? PartA, string? PartB), ushort> _pairs = [];
    private readonly List<(string A, string B, string? PartA, string? PartB)> _pairList = [];

    /// <summary>Adds a fish's speeds, decision and gears.</summary>
    /// <param name="fish">The fish's object of the trace line.</param>
    /// <param name="positionStep">mm per step of the packed data.</param>
    /// <param name="angleStep">rad per step of the packed data.</param>
    public void AddFish(JsonElement fish, double positionStep, double angleStep)
    {
        _motion.Add(Quantise(Optional(fish, "speed") / positionStep));
        _motion.Add(Quantise(Optional(fish, "angularSpeed") / angleStep));
        Codes(fish, "decision");
        Codes(fish, "gears");
    }

    /// <summary>Adds a ball's velocity.</summary>
    /// <param name="ball">The ball's object of the trace line.</param>
    /// <param name="positionStep">mm per step of the packed data.</param>
    public void AddBall(JsonElement ball, double positionStep)
    {
        double vx = 0, vz = 0;
        if (ball.TryGetProperty("velocity", out var v) && v.ValueKind == JsonValueKind.Array && v.GetArrayLength() == 2
            && v[0].ValueKind == JsonValueKind.Number && v[1].ValueKind == JsonValueKind.Number)
        {
            vx = v[0].GetDouble();
            vz = v[1].GetDouble();
        }

        _motion.Add(Quantise(vx / positionStep));
        _motion.Add(Quantise(vz / positionStep));
    }

    /// <summary>Adds the bodies and parts of a contact.</summary>
    /// <param name="contact">The contact's object of the trace line.</param>
    public void AddContact(JsonElement contact)
    {
        var key = (Name(contact, "a") ?? "?", Name(contact, "b") ?? "?", Name(contact, "partA"), Name(contact, "partB"));
        if (!_pairs.TryGetValue(key, out ushort index))
        {
            index = (ushort)Math.Min(_pairList.Count, ushort.MaxValue);
            if (_pairList.Count < ushort.MaxValue)
            {
                _pairs.Add(key, index);
                _pairList.Add(key);
            }
        }

        _contactKinds.Add(index);
    }

    /// <summary>Appends <c>,"motion":…,"decisions":…,"contactKinds":…,"contactPairs":[…]</c> to the page data.</summary>
    /// <param name="s">The page data being written.</param>
    public void Finish(StringBuilder s)
    {
        s.Append(",\"motion\":\"").Append(Convert.ToBase64String(MemoryMarshal.AsBytes(CollectionsMarshal.AsSpan(_motion))))
            .Append("\",\"decisions\":\"").Append(Convert.ToBase64String(CollectionsMarshal.AsSpan(_decisions)))
            .Append("\",\"contactKinds\":\"").Append(Convert.ToBase64String(MemoryMarshal.AsBytes(CollectionsMarshal.AsSpan(_contactKinds))))
            .Append("\",\"contactPairs\":[");
        for (int i = 0; i < _pairList.Count; i++)
        {
            var (a, b, pa, pb) = _pairList[i];
            s.Append(i == 0 ? "[" : ",[").Append(Json(a)).Append(',').Append(Json(b)).Append(',').Append(Json(pa)).Append(',').Append(Json(pb)).Append(']');
        }

        s.Append(']');
    }

    private void Codes(JsonElement fish, string name)
    {
        if (fish.TryGetProperty(name, out var codes) && codes.ValueKind == JsonValueKind.Array && codes.GetArrayLength() == 2)
        {
            foreach (var c in codes.EnumerateArray())
            {
                _decisions.Add(c.ValueKind == JsonValueKind.Number && c.TryGetInt32(out int v) && v is >= 0 and < None ? (byte)v : None);
            }
        }
        else
        {
            _decisions.Add(None);
            _decisions.Add(None);
        }
    }

    private static double Optional(JsonElement o, string name) =>
        o.TryGetProperty(name, out var v) && v.ValueKind == JsonValueKind.Number && double.IsFinite(v.GetDouble()) ? v.GetDouble() : 0;

    private static string? Name(JsonElement o, string name) =>
        o.TryGetProperty(name, out var v) && v.ValueKind == JsonValueKind.String ? v.GetString() : null;

    private static string Json(string? text) => text is null ? "null" : JsonSerializer.Serialize(text, ViewerJsonContext.Default.String);

    private static short Quantise(double v) => (short)Math.Clamp(Math.Round(v), -short.MaxValue, short.MaxValue);
}
