using System.Buffers;
using System.Text.Json;
using URWPGSim2D.Engine.Teams;

namespace URWPGSim2D.Engine.Trace;

/// <summary>
/// Serialises one cycle line of the trace (docs/simulation.md, "Trace"; docs/viewer.md, "Trace
/// additions"): cycle, fish (with the decision each swam by and its gear codes), balls, contacts, score and events, and on the cycle-0 line also the
/// item slug and the static layout. The same bytes go to the trace file, the replay page and the
/// live view. One instance per match; the returned span is valid until the next call.
/// </summary>
internal sealed class TraceLine
{
    private readonly World _world;
    private readonly IMatchTeams _teamSeats;
    private readonly ITraceItemInfo _item;
    private readonly ArrayBufferWriter<byte> _buffer = new(1 << 12);
    private readonly Utf8JsonWriter _json;
    private readonly List<TraceEvent> _events = [];
    private readonly int _teams;

    /// <summary>Creates the serialiser of a match's lines.</summary>
    /// <param name="world">The match's world.</param>
    /// <param name="teams">Who decides for its fish (their names, faults, drawings and logs go into the lines).</param>
    /// <param name="item">The item's information: the match's rules (its item's referee, or the plain scene's).</param>
    public TraceLine(World world, IMatchTeams teams, ITraceItemInfo item)
    {
        _world = world;
        _teamSeats = teams;
        _item = item;
        _json = new Utf8JsonWriter(_buffer);
        _teams = world.TeamCount;
    }

    /// <summary>The item information written into the lines.</summary>
    public ITraceItemInfo Item => _item;

    /// <summary>The line (no newline) of the world's current state and the last cycle's contacts.</summary>
    /// <param name="contacts">The contacts resolved in the cycle just played (empty for cycle 0).</param>
    public ReadOnlySpan<byte> Write(ReadOnlySpan<ContactRecord> contacts)
    {
        var world = _world;
        var w = _json;
        _buffer.ResetWrittenCount();
        w.Reset(_buffer);
        w.WriteStartObject();
        w.WriteNumber("cycle", world.Cycle);
        if (world.Cycle == 0)
        {
            w.WriteString("item", _item.Slug);
            w.WritePropertyName("layout");
            TraceLayout.Write(w, _world, _teamSeats, _item);
        }

        w.WriteStartArray("fish");
        foreach (var f in world.Fish)
        {
            w.WriteStartObject();
            Pair(w, "position", f.Position);
            w.WriteNumber("heading", f.Heading);
            w.WriteStartArray("joints");
            w.WriteNumberValue(f.Joint1);
            w.WriteNumberValue(f.Joint2);
            w.WriteNumberValue(f.Joint3);
            w.WriteEndArray();
            w.WriteNumber("speed", f.Speed.Value);
            w.WriteNumber("angularSpeed", f.Turn.Value);
            if (world.Cycle > 0)
            {
                // The decision the fish swam this cycle by, and where its gear approach stands: the codes its speed and turn rate are at.
                w.WriteStartArray("decision");
                w.WriteNumberValue(f.Decision.VCode);
                w.WriteNumberValue(f.Decision.TCode);
                w.WriteEndArray();
                w.WriteStartArray("gears");
                w.WriteNumberValue(f.Speed.Code);
                w.WriteNumberValue(f.Turn.Code);
                w.WriteEndArray();
            }

            w.WriteEndObject();
        }

        w.WriteEndArray();
        w.WriteStartArray("balls");
        foreach (var b in world.Balls)
        {
            w.WriteStartObject();
            Pair(w, "position", b.Position);
            Pair(w, "velocity", b.Velocity);
            w.WriteEndObject();
        }

        w.WriteEndArray();
        w.WriteStartArray("contacts");
        foreach (ref readonly var c in contacts)
        {
            w.WriteStartObject();
            w.WriteString("a", BodyNames.A(c.Pair));
            w.WriteString("b", BodyNames.B(world, c.Pair));
            w.WriteString("partA", BodyNames.Part(c.PartA));
            w.WriteString("partB", BodyNames.Part(c.PartB));
            Pair(w, "mtv", c.Mtv);
            Pair(w, "normal", c.Normal);
            Pair(w, "actionPoint", c.Point);
            w.WriteEndObject();
        }

        w.WriteEndArray();
        _events.Clear();
        if (world.Cycle > 0)
        {
            _item.AddEvents(world.Cycle, _events);
            AddFaults(world.Cycle);
        }

        w.WriteStartArray("score");
        for (int team = 0; team < _teams; team++)
        {
            w.WriteNumberValue(_item.Score(team));
        }

        w.WriteEndArray();

        w.WriteStartArray("events");
        foreach (var e in _events)
        {
            WriteEvent(w, e);
        }

        w.WriteEndArray();
        WriteDrawings(w);
        WriteLogs(w);
        w.WriteEndObject();
        w.Flush();
        return _buffer.WrittenSpan;
    }

    // A `fault` event per strategy that faulted in this cycle (none for well-behaved strategies, so their lines are unchanged).
    private void AddFaults(int cycle)
    {
        foreach (var slot in _teamSeats.Seats)
        {
            if (slot.LastFaultCycle == cycle)
            {
                _events.Add(new TraceEvent("fault", $"team {slot.Team} ({slot.Label}) {FaultText(slot.LastFaultKind)}: {slot.LastFault}", Team: slot.Team));
            }
        }
    }

    // The strategies' debug drawings of this cycle (run --debug-draw), only on lines where one drew: other lines are unchanged.
    private void WriteDrawings(Utf8JsonWriter w)
    {
        bool any = false;
        foreach (var slot in _teamSeats.Seats)
        {
            var drawn = slot.Drawn;
            if (drawn.IsEmpty)
            {
                continue;
            }

            if (!any)
            {
                w.WriteStartArray("draw");
                any = true;
            }

            foreach (ref readonly var s in drawn)
            {
                DebugShapeJson.Write(w, s, slot.Team);
            }
        }

        if (any)
        {
            w.WriteEndArray();
        }
    }

    // What the strategies printed while deciding this cycle (run --strategy-log), only on lines where one printed.
    private void WriteLogs(Utf8JsonWriter w)
    {
        bool any = false;
        foreach (var slot in _teamSeats.Seats)
        {
            if (slot.Log is not { } log || (log.Length == 0 && log.Dropped == 0))
            {
                continue;
            }

            if (!any)
            {
                w.WriteStartArray("log");
                any = true;
            }

            w.WriteStartObject();
            w.WriteNumber("team", slot.Team);
            w.WriteString("text", log.ToString());
            w.WriteEndObject();
        }

        if (any)
        {
            w.WriteEndArray();
        }
    }

    private static string FaultText(FaultKind kind) => kind switch
    {
        FaultKind.Exception => "exception",
        FaultKind.Timeout => "timeout",
        FaultKind.BadAnswer => "bad answer",
        FaultKind.Disconnected => "remote client disconnected, its fish stop",
        _ => "strategy ended, its fish stop",
    };

    /// <summary>Writes a point as <c>[x, z]</c>.</summary>
    internal static void Pair(Utf8JsonWriter w, string name, Vector2 v)
    {
        w.WriteStartArray(name);
        w.WriteNumberValue(v.X);
        w.WriteNumberValue(v.Y);
        w.WriteEndArray();
    }

    private static void WriteEvent(Utf8JsonWriter w, in TraceEvent e)
    {
        w.WriteStartObject();
        w.WriteString("kind", e.Kind);
        if (e.Team is int team)
        {
            w.WriteNumber("team", team);
        }

        if (e.Fish is int fish)
        {
            w.WriteNumber("fish", fish);
        }

        if (e.Ball is int ball)
        {
            w.WriteNumber("ball", ball);
        }

        if (e.Value is double value)
        {
            w.WriteNumber("value", value);
        }

        w.WriteString("text", e.Text);
        w.WriteEndObject();
    }
}
