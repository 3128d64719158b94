using System.Text.Json;

namespace URWPGSim2D.Tournament.Batch;

/// <summary>
/// The result file of a batch or of one shard, JSON Lines: the header first
/// (<c>{"kind":"batch","scene":…,"shard":I,"shards":K}</c>), then one line per match in match
/// order (<c>{"kind":"match","index":j,"seed":s,"goals":[g0,g1],"contacts":{…},…}</c>). It is
/// written to FILE.partial and renamed, so a stopped run leaves no half file. Nothing in it
/// depends on the machine, so a batch and the merge of its shards give byte-identical files.
/// </summary>
public static class ResultFile
{
    private static readonly JsonWriterOptions Compact = new() { Indented = false };

    /// <summary>Writes the file (via FILE.partial, renamed at the end).</summary>
    public static void Write(string path, BatchHeader header, IReadOnlyList<MatchResult> results)
    {
        string partial = path + ".partial";
        try
        {
            using (var stream = new FileStream(partial, FileMode.Create, FileAccess.Write))
            {
                WriteLine(stream, w => WriteHeader(w, header));
                foreach (var r in results)
                {
                    WriteLine(stream, w => WriteResult(w, r));
                }
            }

            File.Move(partial, path, overwrite: true);
        }
        catch
        {
            File.Delete(partial); // nothing half written stays behind
            throw;
        }
    }

    /// <summary>Reads a file; a bad file throws <see cref="ResultFileException"/> naming the file and line.</summary>
    public static (BatchHeader Header, List<MatchResult> Results) Read(string path)
    {
        string[] lines;
        try
        {
            lines = File.ReadAllLines(path, Encoding.UTF8);
        }
        catch (Exception e) when (e is IOException or UnauthorizedAccessException or ArgumentException or NotSupportedException)
        {
            throw new ResultFileException($"{path}: cannot read the result file ({e.Message})");
        }

        if (lines.Length == 0)
        {
            throw new ResultFileException($"{path}: empty result file");
        }

        BatchHeader header = Parse(path, 1, lines[0], ReadHeader);
        var results = new List<MatchResult>(lines.Length - 1);
        for (int i = 1; i < lines.Length; i++)
        {
            if (lines[i].Length > 0)
            {
                results.Add(Parse(path, i + 1, lines[i], ReadResult));
            }
        }

        return (header, results);
    }

    /// <summary>Writes one compact JSON line (the object <paramref name="write"/> writes, then a line feed).</summary>
    internal static void WriteLine(Stream stream, Action<Utf8JsonWriter> write)
    {
        using (var writer = new Utf8JsonWriter(stream, Compact))
        {
            write(writer);
        }

        stream.WriteByte((byte)'\n');
    }

    private static void WriteHeader(Utf8JsonWriter w, BatchHeader h)
    {
        w.WriteStartObject();
        w.WriteString("kind", "batch");
        w.WriteString("scene", h.Scene);
        w.WriteString("strategies", h.Strategies);
        w.WriteString("teams", h.Teams);
        w.WriteString("noise", h.Noise);
        w.WriteNumber("strategyTimeoutMs", h.StrategyTimeoutMs);
        w.WriteNumber("firstSeed", h.FirstSeed);
        w.WriteNumber("matches", h.Matches);
        w.WriteNumber("cycles", h.Cycles);
        w.WriteNumber("shard", h.ShardIndex);
        w.WriteNumber("shards", h.ShardCount);
        w.WriteEndObject();
    }

    /// <summary>Writes a match line's object; <paramref name="extra"/> adds fields at its end (a tournament's entrants).</summary>
    internal static void WriteResult(Utf8JsonWriter w, MatchResult r, Action<Utf8JsonWriter>? extra = null)
    {
        w.WriteStartObject();
        w.WriteString("kind", "match");
        w.WriteNumber("index", r.Index);
        w.WriteNumber("seed", r.Seed);
        w.WriteNumber("cycles", r.Cycles);
        w.WriteStartArray("goals");
        w.WriteNumberValue(r.Goals0);
        w.WriteNumberValue(r.Goals1);
        w.WriteEndArray();
        w.WriteStartObject("contacts");
        for (int k = 0; k < MatchResult.ContactNames.Length; k++)
        {
            w.WriteNumber(MatchResult.ContactNames[k], r.Contacts[k]);
        }

        w.WriteEndObject();
        w.WriteNumber("subSteps", r.SubSteps);
        w.WriteNumber("mostSubSteps", r.MostSubSteps);
        w.WriteNumber("events", r.Events);
        w.WriteNumber("leftoverOverlap", r.LeftoverOverlap);
        w.WriteNumber("leftoverCycle", r.LeftoverCycle);
        w.WriteNumber("strategyFaults", r.StrategyFaults);
        if (r.Faults is { Length: > 0 })
        {
            // Compatible addition: per team, the faults of each strategy that faulted (absent when none did).
            w.WriteStartArray("faults");
            foreach (var f in r.Faults)
            {
                w.WriteStartObject();
                w.WriteNumber("team", f.Team);
                w.WriteString("strategy", f.Strategy);
                w.WriteNumber("exceptions", f.Exceptions);
                w.WriteNumber("timeouts", f.Timeouts);
                w.WriteNumber("badAnswers", f.BadAnswers);
                if (f.Crashes > 0)
                {
                    w.WriteNumber("crashes", f.Crashes); // compatible addition: present only when the host ended
                }

                w.WriteString("first", f.First);
                w.WriteEndObject();
            }

            w.WriteEndArray();
        }

        if (r.Item is not null)
        {
            // Compatible additions of a competition item: its slug, score per team, winner (−1: none) and the deciding rule.
            w.WriteString("item", r.Item);
            w.WriteStartArray("score");
            foreach (int score in r.Scores ?? [])
            {
                w.WriteNumberValue(score);
            }

            w.WriteEndArray();
            w.WriteNumber("winner", r.Winner);
            w.WriteString("rule", r.Rule);
        }

        if (r.Failed is not null)
        {
            w.WriteString("failed", r.Failed); // compatible addition: present only for a match that failed inside the server
        }

        extra?.Invoke(w);
        w.WriteEndObject();
    }

    /// <summary>Parses one line with <paramref name="read"/>; any failure is a <see cref="ResultFileException"/> naming the file and line.</summary>
    internal static T Parse<T>(string path, int line, string text, Func<JsonElement, T> read)
    {
        try
        {
            using var document = JsonDocument.Parse(text);
            return read(document.RootElement);
        }
        catch (Exception e) when (e is JsonException or KeyNotFoundException or InvalidOperationException or FormatException or ResultFileException)
        {
            throw new ResultFileException($"{path}:{line}: {e.Message.ReplaceLineEndings(" ")}");
        }
    }

    private static BatchHeader ReadHeader(JsonElement e)
    {
        Kind(e, "batch");
        var header = new BatchHeader(
            Field(e, "scene").GetString()!, Field(e, "strategies").GetString()!, Field(e, "teams").GetString()!,
            Field(e, "noise").GetString()!, Field(e, "strategyTimeoutMs").GetInt32(), Field(e, "firstSeed").GetUInt64(),
            Field(e, "matches").GetInt32(), Field(e, "cycles").GetInt32(), Field(e, "shard").GetInt32(),
            Field(e, "shards").GetInt32());
        if (header.Matches < 1 || header.ShardCount < 1 || header.ShardIndex < 0 || header.ShardIndex >= header.ShardCount)
        {
            throw new ResultFileException($"header says shard {header.ShardIndex}/{header.ShardCount} of {header.Matches} matches, which is not a valid share");
        }

        return header;
    }

    /// <summary>Reads a match line's object; a bad one throws (<see cref="ResultFileException"/>, <see cref="JsonException"/>, …, as <see cref="Parse{T}"/> catches).</summary>
    internal static MatchResult ReadResult(JsonElement e)
    {
        Kind(e, "match");
        int index = Field(e, "index").GetInt32();
        ulong seed = Field(e, "seed").GetUInt64();
        int cycles = Field(e, "cycles").GetInt32();
        var goals = Field(e, "goals");
        if (goals.ValueKind != JsonValueKind.Array || goals.GetArrayLength() != 2)
        {
            throw new ResultFileException($"\"goals\" must be an array of 2 counts (one per team), got {Short(goals.GetRawText())}");
        }

        int goals0 = goals[0].GetInt32(), goals1 = goals[1].GetInt32();
        var contacts = Field(e, "contacts");
        var counts = new long[MatchResult.ContactNames.Length];
        for (int k = 0; k < counts.Length; k++)
        {
            counts[k] = Field(contacts, MatchResult.ContactNames[k]).GetInt64();
        }

        long subSteps = Field(e, "subSteps").GetInt64();
        int mostSubSteps = Field(e, "mostSubSteps").GetInt32();
        long events = Field(e, "events").GetInt64();
        float overlap = Field(e, "leftoverOverlap").GetSingle();
        if (!float.IsFinite(overlap) || overlap < 0f)
        {
            throw new ResultFileException($"\"leftoverOverlap\" must be a finite number >= 0, got {Short(Field(e, "leftoverOverlap").GetRawText())}");
        }

        int overlapCycle = Field(e, "leftoverCycle").GetInt32();
        int faults = Field(e, "strategyFaults").GetInt32();
        var result = new MatchResult(index, seed, cycles, goals0, goals1, counts, subSteps, mostSubSteps, events, overlap, overlapCycle, faults);
        if (e.TryGetProperty("faults", out var perTeam))
        {
            result = result with { Faults = ReadFaults(perTeam, faults) };
        }

        if (e.TryGetProperty("item", out var item))
        {
            var score = Field(e, "score");
            var scores = new int[score.GetArrayLength()];
            for (int t = 0; t < scores.Length; t++)
            {
                scores[t] = score[t].GetInt32();
            }

            result = result with { Item = item.GetString(), Scores = scores, Winner = Field(e, "winner").GetInt32(), Rule = Field(e, "rule").GetString() };
        }

        if (e.TryGetProperty("failed", out var failed))
        {
            result = result with { Failed = failed.GetString() };
        }

        return result;
    }

    private static TeamFaults[] ReadFaults(JsonElement list, int total)
    {
        if (list.ValueKind != JsonValueKind.Array || list.GetArrayLength() == 0)
        {
            throw new ResultFileException($"\"faults\" must be a non-empty array of per-team faults, got {Short(list.GetRawText())}");
        }

        var faults = new TeamFaults[list.GetArrayLength()];
        int sum = 0;
        for (int i = 0; i < faults.Length; i++)
        {
            var f = list[i];
            int team = Field(f, "team").GetInt32();
            int exceptions = Field(f, "exceptions").GetInt32(), timeouts = Field(f, "timeouts").GetInt32(), bad = Field(f, "badAnswers").GetInt32();
            int crashes = f.TryGetProperty("crashes", out var crashed) ? crashed.GetInt32() : 0;
            if (team is < 0 or > 3 || exceptions < 0 || timeouts < 0 || bad < 0 || crashes is < 0 or > 1 || exceptions + timeouts + bad + crashes == 0)
            {
                throw new ResultFileException($"\"faults\"[{i}] must name team 0 to 3 and counts >= 0 that are not all 0, got {Short(f.GetRawText())}");
            }

            faults[i] = new TeamFaults(team, Field(f, "strategy").GetString()!, exceptions, timeouts, bad, Field(f, "first").GetString()!, crashes);
            sum += faults[i].Total;
        }

        if (sum != total)
        {
            throw new ResultFileException($"\"faults\" add up to {sum}, but \"strategyFaults\" is {total}");
        }

        return faults;
    }

    private static string Short(string raw) => raw.Length <= 40 ? raw : raw[..37] + "...";

    private static JsonElement Field(JsonElement e, string name) =>
        e.ValueKind == JsonValueKind.Object && e.TryGetProperty(name, out var value) ? value : throw new ResultFileException($"missing field \"{name}\"");

    private static void Kind(JsonElement e, string kind)
    {
        string? actual = e.ValueKind == JsonValueKind.Object && e.TryGetProperty("kind", out var k) ? k.GetString() : null;
        if (actual != kind)
        {
            throw new ResultFileException($"expected a \"{kind}\" line, got {(actual is null ? "something else" : $"\"{actual}\"")}");
        }
    }
}
