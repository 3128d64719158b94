using System;
using System.IO;
using System.Numerics;
using System.Text.Json;
using URWPGSim2D.Server.Simulation;

namespace URWPGSim2D.Server.Trace;

/// <summary>
/// Writes the match as JSON Lines: the initial state as cycle 0, then one line per cycle with every
/// fish (position, heading, joints, speed, angular speed), every ball (position, velocity) and the
/// cycle's resolved contacts (ids, fish parts, MTV of a, normal from b toward a, action point).
/// Numbers use the shortest round-trip form, so the same match gives the same bytes. The file is
/// written under a temporary name beside the target and renamed by <see cref="Complete"/>; if the
/// run fails, <see cref="Dispose"/> deletes it, so no half trace is left.
/// </summary>
internal sealed class TraceWriter : IDisposable
{
    private static readonly byte[] NewLine = [(byte)'\n'];

    private readonly string _path;
    private readonly string _temporary;
    private readonly FileStream _stream;
    private readonly Utf8JsonWriter _json;
    private readonly ITraceItemInfo? _item;
    private bool _completed;

    /// <summary>Opens the trace (as FILE.partial).</summary>
    /// <param name="path">The trace file.</param>
    /// <param name="item">The item's score, events and layout additions, or null for the plain lines.</param>
    public TraceWriter(string path, ITraceItemInfo? item = null)
    {
        _item = item;
        _path = Path.GetFullPath(path);
        _temporary = _path + ".partial";
        _stream = new FileStream(_temporary, FileMode.Create, FileAccess.Write, FileShare.None, 1 << 16);
        _json = new Utf8JsonWriter(_stream, new JsonWriterOptions { SkipValidation = false });
    }

    /// <summary>Writes one line for the world's current state and the last cycle's contacts.</summary>
    public void WriteCycle(World world, ReadOnlySpan<ContactRecord> contacts)
    {
        var w = _json;
        w.WriteStartObject();
        w.WriteNumber("cycle", world.Cycle);
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
        if (_item is not null)
        {
            TraceItemLines.Write(w, world, _item);
        }

        w.WriteEndObject();
        w.Flush();
        _stream.Write(NewLine);
        w.Reset();
    }

    /// <summary>Flushes the trace and moves it to its final name.</summary>
    public void Complete()
    {
        _json.Dispose();
        _stream.Dispose();
        File.Move(_temporary, _path, overwrite: true);
        _completed = true;
    }

    /// <summary>Closes the file; an incomplete trace is deleted.</summary>
    public void Dispose()
    {
        if (_completed)
        {
            return;
        }

        _json.Dispose();
        _stream.Dispose();
        File.Delete(_temporary);
    }

    private static void Pair(Utf8JsonWriter w, string name, Vector2 v)
    {
        w.WriteStartArray(name);
        w.WriteNumberValue(v.X);
        w.WriteNumberValue(v.Y);
        w.WriteEndArray();
    }
}
