using System.Collections.Generic;

namespace URWPGSim2D.Protocol;

/// <summary>
/// Reads <c>cycle</c> messages into one client-side <see cref="MatchSnapshot"/> (made from the
/// assignment), so the strategy sees exactly what an in-process strategy sees: the same fish, balls,
/// score, item variables (in the same order) and half-time swap. Variable strings are kept while
/// they do not change, so a cycle allocates nothing in a steady state.
/// </summary>
public sealed class CycleReader
{
    private readonly AssignmentMessage _assignment;
    private readonly List<string> _keys = [];
    private readonly List<string> _values = [];
    private OrderedVariables _variables = new();
    private readonly MatchSnapshotWriter _view;
    private byte[] _packed = [];

    /// <summary>Creates the reader and the snapshot it fills.</summary>
    public CycleReader(AssignmentMessage assignment)
    {
        ArgumentNullException.ThrowIfNull(assignment);
        _assignment = assignment;
        _view = assignment.CreateSnapshotWriter();
        _view.SetItem(assignment.ItemName, _variables, assignment.TotalCycles);
    }

    /// <summary>The snapshot the strategy reads.</summary>
    public MatchSnapshot Snapshot => _view.Snapshot;

    /// <summary>Reads a <c>cycle</c> message into <see cref="Snapshot"/>; returns its cycle number.</summary>
    public int Read(ReadOnlySpan<byte> line)
    {
        try
        {
            var r = new Utf8JsonReader(line);
            JsonFields.StartObject(ref r);
            int? cycle = null;
            int fish = -1, balls = -1;
            Span<int> goals = stackalloc int[MessageReader.MaxTeams];
            int teams = 2;
            bool swapped = false;
            while (JsonFields.NextProperty(ref r))
            {
                if (r.ValueTextEquals("cycle"u8))
                {
                    cycle = JsonFields.Int(ref r, "cycle");
                }
                else if (r.ValueTextEquals("goals"u8))
                {
                    teams = MessageReader.Goals(ref r, goals);
                }
                else if (r.ValueTextEquals("sidesSwapped"u8))
                {
                    swapped = JsonFields.Bool(ref r, "sidesSwapped");
                }
                else if (r.ValueTextEquals("variables"u8))
                {
                    Variables(ref r);
                }
                else if (r.ValueTextEquals("fish"u8))
                {
                    fish = Fish(ref r);
                }
                else if (r.ValueTextEquals("balls"u8))
                {
                    balls = Balls(ref r);
                }
                else if (r.ValueTextEquals("packed"u8))
                {
                    Packed(ref r);
                    (fish, balls) = (_assignment.FishCount, _assignment.BallCount);
                }
                else
                {
                    JsonFields.Skip(ref r);
                }
            }

            if (fish != _assignment.FishCount)
            {
                throw new ProtocolException(fish < 0 ? "fish: missing" : $"fish: {fish} fish, the assignment said {_assignment.FishCount}");
            }

            if (balls != _assignment.BallCount)
            {
                throw new ProtocolException(balls < 0 ? "balls: missing" : $"balls: {balls} balls, the assignment said {_assignment.BallCount}");
            }

            int c = cycle ?? throw MessageReader.Missing("cycle");
            _view.SetHeader(c, goals[..teams]);
            _view.SetSidesSwapped(swapped);
            return c;
        }
        catch (JsonException e)
        {
            throw MessageReader.NotJson(e);
        }
    }

    // The fish and balls of a packed cycle (PackedCycle): base64 of their bytes, decoded in a reused buffer.
    private void Packed(ref Utf8JsonReader r)
    {
        r.Read();
        if (r.TokenType != JsonTokenType.String)
        {
            throw new ProtocolException($"packed: expected a string, got {JsonFields.Describe(ref r)}");
        }

        int length = r.HasValueSequence ? (int)r.ValueSequence.Length : r.ValueSpan.Length;
        if (_packed.Length < length)
        {
            _packed = new byte[length];
        }

        int copied = r.CopyString(_packed);
        if (System.Buffers.Text.Base64.DecodeFromUtf8InPlace(_packed.AsSpan(0, copied), out int bytes) != System.Buffers.OperationStatus.Done)
        {
            throw new ProtocolException("packed: not base64");
        }

        PackedCycle.Read(_packed.AsSpan(0, bytes), _view.Fish, _view.Balls);
    }

    private void Variables(ref Utf8JsonReader r)
    {
        JsonFields.StartObjectValue(ref r, "variables");
        int i = 0;
        bool sameKeys = true;
        while (JsonFields.NextProperty(ref r))
        {
            if (!(sameKeys && i < _keys.Count && r.ValueTextEquals(_keys[i])))
            {
                sameKeys = false;
                _keys.RemoveRange(i, _keys.Count - i);
                _values.RemoveRange(Math.Min(i, _values.Count), _values.Count - Math.Min(i, _values.Count));
                _keys.Add(r.GetString()!);
            }

            r.Read();
            if (r.TokenType != JsonTokenType.String)
            {
                throw new ProtocolException($"variables.{_keys[i]}: expected a string, got {JsonFields.Describe(ref r)}");
            }

            if (i < _values.Count)
            {
                if (!r.ValueTextEquals(_values[i]))
                {
                    _values[i] = r.GetString()!;
                    _variables.Set(_keys[i], _values[i]);
                }
            }
            else
            {
                _values.Add(r.GetString()!);
            }

            i++;
        }

        if (!sameKeys || i != _keys.Count)
        {
            _keys.RemoveRange(i, _keys.Count - i);
            _values.RemoveRange(i, _values.Count - i);
            _variables = new OrderedVariables();
            for (int k = 0; k < _keys.Count; k++)
            {
                _variables.Set(_keys[k], _values[k]);
            }

            _view.SetItem(_assignment.ItemName, _variables, _assignment.TotalCycles);
        }
    }

    private int Fish(ref Utf8JsonReader r)
    {
        JsonFields.StartArray(ref r, "fish");
        var buffer = _view.Fish;
        int n = 0;
        Span<float> three = stackalloc float[3];
        while (JsonFields.NextObject(ref r, "fish", n, buffer.Length))
        {
            int index = -1, team = -1, seen = 0, v = 0, t = 7;
            Vector2 position = default;
            float heading = 0, speed = 0, angular = 0, body = 0, head = 0, width = 0, j1 = 0, j2 = 0, j3 = 0, t1 = 0, t2 = 0, t3 = 0;
            while (JsonFields.NextProperty(ref r))
            {
                if (r.ValueTextEquals("index"u8))
                {
                    index = JsonFields.Int(ref r, "fish.index");
                    seen |= 1;
                }
                else if (r.ValueTextEquals("team"u8))
                {
                    team = JsonFields.Int(ref r, "fish.team");
                    seen |= 2;
                }
                else if (r.ValueTextEquals("position"u8))
                {
                    position = JsonFields.Vector(ref r, "fish.position");
                    seen |= 4;
                }
                else if (r.ValueTextEquals("heading"u8))
                {
                    heading = JsonFields.Float(ref r, "fish.heading");
                    seen |= 8;
                }
                else if (r.ValueTextEquals("speed"u8))
                {
                    speed = JsonFields.Float(ref r, "fish.speed");
                    seen |= 16;
                }
                else if (r.ValueTextEquals("angularSpeed"u8))
                {
                    angular = JsonFields.Float(ref r, "fish.angularSpeed");
                    seen |= 32;
                }
                else if (r.ValueTextEquals("bodyLength"u8))
                {
                    body = JsonFields.Float(ref r, "fish.bodyLength");
                    seen |= 64;
                }
                else if (r.ValueTextEquals("headLength"u8))
                {
                    head = JsonFields.Float(ref r, "fish.headLength");
                    seen |= 128;
                }
                else if (r.ValueTextEquals("width"u8))
                {
                    width = JsonFields.Float(ref r, "fish.width");
                    seen |= 256;
                }
                else if (r.ValueTextEquals("joints"u8))
                {
                    JsonFields.Floats(ref r, "fish.joints", three);
                    (j1, j2, j3) = (three[0], three[1], three[2]);
                    seen |= 512;
                }
                else if (r.ValueTextEquals("tailLengths"u8))
                {
                    JsonFields.Floats(ref r, "fish.tailLengths", three);
                    (t1, t2, t3) = (three[0], three[1], three[2]);
                    seen |= 1024;
                }
                else if (r.ValueTextEquals("decision"u8))
                {
                    JsonFields.Floats(ref r, "fish.decision", three[..2]);
                    (v, t) = ((int)three[0], (int)three[1]);
                    seen |= 2048;
                }
                else
                {
                    JsonFields.Skip(ref r);
                }
            }

            if (seen != 4095)
            {
                throw new ProtocolException($"fish[{n}]: a field is missing (index, team, position, heading, speed, angularSpeed, bodyLength, headLength, width, joints, tailLengths, decision)");
            }

            buffer[n] = new FishView(index, team, position, heading, speed, angular, body, head, new Decision(v, t))
            {
                Width = width,
                Joint1 = j1,
                Joint2 = j2,
                Joint3 = j3,
                TailLength1 = t1,
                TailLength2 = t2,
                TailLength3 = t3,
            };
            n++;
        }

        return n;
    }

    private int Balls(ref Utf8JsonReader r)
    {
        JsonFields.StartArray(ref r, "balls");
        var buffer = _view.Balls;
        int n = 0;
        while (JsonFields.NextObject(ref r, "balls", n, buffer.Length))
        {
            int index = -1, seen = 0;
            Vector2 position = default, velocity = default;
            float radius = 0;
            while (JsonFields.NextProperty(ref r))
            {
                if (r.ValueTextEquals("index"u8))
                {
                    index = JsonFields.Int(ref r, "balls.index");
                    seen |= 1;
                }
                else if (r.ValueTextEquals("position"u8))
                {
                    position = JsonFields.Vector(ref r, "balls.position");
                    seen |= 2;
                }
                else if (r.ValueTextEquals("velocity"u8))
                {
                    velocity = JsonFields.Vector(ref r, "balls.velocity");
                    seen |= 4;
                }
                else if (r.ValueTextEquals("radius"u8))
                {
                    radius = JsonFields.Float(ref r, "balls.radius");
                    seen |= 8;
                }
                else
                {
                    JsonFields.Skip(ref r);
                }
            }

            if (seen != 15)
            {
                throw new ProtocolException($"balls[{n}]: a field is missing (index, position, velocity, radius)");
            }

            buffer[n] = new BallView(index, position, velocity, radius);
            n++;
        }

        return n;
    }
}
