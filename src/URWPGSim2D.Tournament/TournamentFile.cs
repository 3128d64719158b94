using System.Text.Json;

namespace URWPGSim2D.Tournament;

/// <summary>
/// A tournament's result file, JSON Lines: the header
/// (<c>{"kind":"tournament","item":…,"entrants":[{"name":…,"spec":…[,"version":…]}],…,"shard":I,"shards":K}</c>),
/// then one line per match: a batch match line (docs/batch.md) with <c>"entrants":[NAME, …]</c>
/// (per team) added at its end, or <c>{"kind":"forfeit","index":j,"seed":s,"entrants":[…],"forfeits":[team…],"reasons":[…]}</c>
/// for a match an entrant could not be loaded for. Written whole through FILE.partial and renamed,
/// in index order, so the same results give the same bytes; while a run plays, finished lines are
/// appended, so a stopped run keeps them. Reading keeps every whole, valid line and counts the
/// others (a cut last line, garbage): they are played again.
/// </summary>
public static class TournamentFile
{
    /// <summary>Writes the file whole (through FILE.partial, renamed).</summary>
    public static void Write(string path, TournamentHeader header, IEnumerable<TournamentRecord> records)
    {
        string partial = path + ".partial";
        try
        {
            using (var stream = new FileStream(partial, FileMode.Create, FileAccess.Write))
            {
                ResultFile.WriteLine(stream, w => WriteHeader(w, header));
                foreach (var r in records)
                {
                    WriteRecord(stream, r);
                }
            }

            File.Move(partial, path, overwrite: true);
        }
        catch
        {
            File.Delete(partial);
            throw;
        }
    }

    /// <summary>Writes a forfeit's <c>"forfeits"</c> (its teams that forfeit) and <c>"reasons"</c> (one line each) as a record's line has them.</summary>
    public static void WriteForfeits(Utf8JsonWriter w, TournamentRecord r)
    {
        ArgumentNullException.ThrowIfNull(w);
        ArgumentNullException.ThrowIfNull(r);
        w.WriteStartArray("forfeits");
        foreach (int team in r.Forfeits)
        {
            w.WriteNumberValue(team);
        }

        w.WriteEndArray();
        w.WriteStartArray("reasons");
        foreach (string reason in r.Reasons)
        {
            w.WriteStringValue(reason);
        }

        w.WriteEndArray();
    }

    /// <summary>Writes one record's line to an open file.</summary>
    public static void WriteRecord(Stream stream, TournamentRecord r)
    {
        if (r.Result is { } result)
        {
            ResultFile.WriteLine(stream, w => ResultFile.WriteResult(w, result, x => Names(x, r.Entrants)));
            return;
        }

        ResultFile.WriteLine(stream, w =>
        {
            w.WriteStartObject();
            w.WriteString("kind", "forfeit");
            w.WriteNumber("index", r.Index);
            w.WriteNumber("seed", r.Seed);
            Names(w, r.Entrants);
            WriteForfeits(w, r);
            if (r.Failed)
            {
                w.WriteBoolean("failed", true);
            }

            w.WriteEndObject();
        });
    }

    /// <summary>Reads one record's line, as <see cref="WriteRecord"/> writes it (without its line feed).</summary>
    /// <param name="line">The line.</param>
    /// <exception cref="ResultFileException">The line is not a record.</exception>
    public static TournamentRecord ParseRecord(string line) => ResultFile.Parse("record", 1, line, ReadRecord);

    /// <summary>Reads a file: its header, its valid records (in file order) and how many lines were not valid.</summary>
    /// <exception cref="ResultFileException">The file cannot be read or its first line is not a tournament header.</exception>
    public static (TournamentHeader Header, List<TournamentRecord> Records, int Broken) Read(string path)
    {
        string text;
        try
        {
            text = File.ReadAllText(path, Encoding.UTF8);
        }
        catch (Exception e) when (e is IOException or UnauthorizedAccessException or ArgumentException or NotSupportedException)
        {
            throw new ResultFileException($"{path}: cannot read the result file ({e.Message})");
        }

        var lines = text.Split('\n');
        if (lines.Length < 2)
        {
            throw new ResultFileException($"{path}: not a tournament result file (no whole header line)");
        }

        var header = ResultFile.Parse(path, 1, lines[0], ReadHeader);
        var records = new List<TournamentRecord>(lines.Length);
        int broken = 0;
        for (int i = 1; i < lines.Length; i++)
        {
            bool last = i == lines.Length - 1; // after the final line feed: empty, or a line cut short
            if (lines[i].Length == 0)
            {
                continue;
            }

            if (last)
            {
                broken++;
                continue;
            }

            try
            {
                records.Add(ResultFile.Parse(path, i + 1, lines[i], ReadRecord));
            }
            catch (ResultFileException)
            {
                broken++;
            }
        }

        return (header, records, broken);
    }

    private static void Names(Utf8JsonWriter w, IReadOnlyList<string> names)
    {
        w.WriteStartArray("entrants");
        foreach (string name in names)
        {
            w.WriteStringValue(name);
        }

        w.WriteEndArray();
    }

    private static void WriteHeader(Utf8JsonWriter w, TournamentHeader h)
    {
        w.WriteStartObject();
        w.WriteString("kind", "tournament");
        w.WriteString("item", h.Item);
        w.WriteStartArray("entrants");
        foreach (var e in h.Entrants)
        {
            w.WriteStartObject();
            w.WriteString("name", e.Name);
            w.WriteString("spec", e.Spec);
            if (e.Version is not null)
            {
                w.WriteString("version", e.Version);
            }

            w.WriteEndObject();
        }

        w.WriteEndArray();
        w.WriteNumber("seeds", h.Seeds);
        w.WriteNumber("firstSeed", h.FirstSeed);
        w.WriteNumber("cycles", h.Cycles);
        w.WriteNumber("strategyTimeoutMs", h.StrategyTimeoutMs);
        w.WriteNumber("matches", h.Matches);
        w.WriteNumber("shard", h.ShardIndex);
        w.WriteNumber("shards", h.ShardCount);
        w.WriteEndObject();
    }

    private static TournamentHeader ReadHeader(JsonElement e)
    {
        if (Field(e, "kind").GetString() != "tournament")
        {
            throw new ResultFileException("not a tournament result file (its first line is not a \"tournament\" header)");
        }

        var list = Field(e, "entrants");
        var entrants = new List<Entrant>();
        foreach (var x in list.EnumerateArray())
        {
            entrants.Add(new Entrant(Field(x, "name").GetString()!, Field(x, "spec").GetString()!, x.TryGetProperty("version", out var v) ? v.GetString() : null));
        }

        var h = new TournamentHeader(
            Field(e, "item").GetString()!, entrants, Field(e, "seeds").GetInt32(), Field(e, "firstSeed").GetUInt64(),
            Field(e, "cycles").GetInt32(), Field(e, "strategyTimeoutMs").GetInt32(), Field(e, "matches").GetInt32(),
            Field(e, "shard").GetInt32(), Field(e, "shards").GetInt32());
        if (h.ShardCount < 1 || h.ShardIndex < 0 || h.ShardIndex >= h.ShardCount || h.Matches < 0)
        {
            throw new ResultFileException($"header says shard {h.ShardIndex}/{h.ShardCount} of {h.Matches} matches, which is not a valid share");
        }

        return h;
    }

    private static TournamentRecord ReadRecord(JsonElement e)
    {
        var names = new List<string>();
        foreach (var x in Field(e, "entrants").EnumerateArray())
        {
            names.Add(x.GetString() ?? throw new ResultFileException("an entrant's name is null"));
        }

        string? kind = Field(e, "kind").GetString();
        if (kind == "forfeit")
        {
            var forfeits = new List<int>();
            foreach (var x in Field(e, "forfeits").EnumerateArray())
            {
                forfeits.Add(x.GetInt32());
            }

            var reasons = new List<string>();
            foreach (var x in Field(e, "reasons").EnumerateArray())
            {
                reasons.Add(x.GetString() ?? string.Empty);
            }

            if (forfeits.Count == 0 || forfeits.Count != reasons.Count)
            {
                throw new ResultFileException("a forfeit needs as many reasons as forfeiting teams, at least one");
            }

            bool failed = e.TryGetProperty("failed", out var f) && f.GetBoolean();
            return new TournamentRecord(Field(e, "index").GetInt32(), Field(e, "seed").GetUInt64(), names, null, forfeits, reasons, failed);
        }

        var result = ResultFile.ReadResult(e);
        return new TournamentRecord(result.Index, result.Seed, names, result, [], []);
    }

    private static JsonElement Field(JsonElement e, string name) =>
        e.ValueKind == JsonValueKind.Object && e.TryGetProperty(name, out var value) ? value : throw new ResultFileException($"missing field \"{name}\"");
}
