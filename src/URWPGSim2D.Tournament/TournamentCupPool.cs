namespace URWPGSim2D.Tournament;

/// <summary>
/// The matches a group stage and knockout's folder already holds, found by what they are (their seed and
/// the entrants on each side) rather than by their index, since the knockout's layout follows the results:
/// a record is kept when every one of its entrants is still in the tournament in the same version (a
/// forfeit only while its forfeiting entrants still cannot be loaded). Replay pages of kept records are set
/// aside at the start (<c>match-J.html.kept</c>) and put at their match's new index at the end
/// (<see cref="PlaceReplays"/>); the others are deleted, as their index may now be another match's.
/// </summary>
public sealed class TournamentCupPool
{
    private readonly Dictionary<string, TournamentRecord> _records = new(StringComparer.Ordinal);
    private readonly Dictionary<string, string> _pages = new(StringComparer.Ordinal);
    private readonly string _folder;
    private readonly IReadOnlyList<string> _names;

    private TournamentCupPool(string folder, IReadOnlyList<string> names)
    {
        _folder = folder;
        _names = names;
    }

    /// <summary>Lines of the file that were not valid.</summary>
    public int Broken { get; private set; }

    /// <summary>Records of entrants that changed their code or left the tournament, dropped.</summary>
    public int Changed { get; private set; }

    /// <summary>The kept records, as read (their old indices).</summary>
    public IReadOnlyList<TournamentRecord> Records => [.. _records.Values];

    /// <summary>Reads the folder's results (when there are any) and sets the kept records' replay pages aside.</summary>
    /// <param name="results">The result file.</param>
    /// <param name="header">The tournament asked for (the file's settings are the same: checked before).</param>
    /// <param name="errors">Per entrant, why it cannot be loaded now, or null.</param>
    /// <param name="folder">The tournament's folder (its replays/ sub-folder).</param>
    /// <exception cref="Batch.ResultFileException">The file cannot be read or is not a tournament's.</exception>
    public static TournamentCupPool Read(string results, TournamentHeader header, IReadOnlyList<string?> errors, string folder)
    {
        var pool = new TournamentCupPool(folder, [.. header.Entrants.Select(e => e.Name)]);
        var byOldIndex = new Dictionary<int, string?>();
        if (File.Exists(results))
        {
            var (found, records, broken) = TournamentFile.Read(results);
            pool.Broken = broken;
            var now = new Dictionary<string, int>(StringComparer.Ordinal);
            for (int i = 0; i < header.Entrants.Count; i++)
            {
                now[header.Entrants[i].Name] = i;
            }

            var then = found.Entrants.ToDictionary(e => e.Name, StringComparer.Ordinal);
            foreach (var r in records)
            {
                if (r.Entrants.Count != 2 || r.Forfeits.Any(f => f is < 0 or > 1) || (r.Result is { } result && result.Seed != r.Seed) || r.Entrants[0] == r.Entrants[1])
                {
                    pool.Broken++;
                    continue;
                }

                if (!r.Entrants.All(n => now.TryGetValue(n, out int e) && then.TryGetValue(n, out var was) && header.Entrants[e] == was))
                {
                    pool.Changed++;
                    continue;
                }

                if (!r.Failed && r.Forfeits.Any(f => errors[now[r.Entrants[f]]] is null))
                {
                    continue; // its entrant loads now: the match is played
                }

                string key = Key(r.Seed, r.Entrants);
                pool._records[key] = r;
                byOldIndex[r.Index] = byOldIndex.ContainsKey(r.Index) ? null : key;
            }
        }

        string pages = Path.Combine(folder, TournamentOutputs.Replays);
        if (Directory.Exists(pages))
        {
            foreach (string page in Directory.EnumerateFiles(pages, "match-*.html*"))
            {
                string name = Path.GetFileName(page);
                string number = name["match-".Length..name.IndexOf(".html", StringComparison.Ordinal)];
                if (name.EndsWith(".html", StringComparison.Ordinal)
                    && int.TryParse(number, NumberStyles.None, CultureInfo.InvariantCulture, out int index)
                    && byOldIndex.TryGetValue(index, out string? key) && key is not null)
                {
                    string aside = page + ".kept";
                    File.Move(page, aside, overwrite: true);
                    pool._pages[key] = aside;
                }
                else
                {
                    File.Delete(page);
                }
            }
        }

        return pool;
    }

    /// <summary>A match's record when the pool holds it, else null.</summary>
    public TournamentRecord? Find(ScheduledMatch m) => _records.GetValueOrDefault(Key(m));

    /// <summary>Whether the pool holds the match.</summary>
    public bool Has(ScheduledMatch m) => _records.ContainsKey(Key(m));

    /// <summary>Whether the match has a replay page: one set aside, or written at its index when it was played; a forfeit needs none.</summary>
    public bool HasReplay(ScheduledMatch m) =>
        Find(m) is { IsForfeit: true } || _pages.ContainsKey(Key(m)) || File.Exists(TournamentOutputs.ReplayPage(_folder, m.Index));

    /// <summary>Adds the record of a match just played (its replay page, if any, is already at its index).</summary>
    public void Add(ScheduledMatch m, TournamentRecord record)
    {
        string key = Key(m);
        _records[key] = record;
        if (_pages.Remove(key, out string? aside))
        {
            File.Delete(aside);
        }
    }

    /// <summary>The match's record at its index in the layout.</summary>
    public TournamentRecord At(ScheduledMatch m)
    {
        var r = _records[Key(m)];
        return r.Index == m.Index ? r : r with { Index = m.Index, Result = r.Result is { } result ? result with { Index = m.Index } : null };
    }

    /// <summary>Puts each set-aside replay page at its match's index in the layout, and deletes the others.</summary>
    public void PlaceReplays(Bracket bracket)
    {
        foreach (var m in bracket.Matches)
        {
            if (_pages.Remove(Key(m), out string? aside))
            {
                File.Move(aside, TournamentOutputs.ReplayPage(_folder, m.Index), overwrite: true);
            }
        }

        foreach (string aside in _pages.Values)
        {
            File.Delete(aside);
        }

        _pages.Clear();
    }

    private string Key(ScheduledMatch m) => Key(m.Seed, [.. m.Sides.Select(s => _names[s])]);

    private static string Key(ulong seed, IReadOnlyList<string> names) => seed.ToString(CultureInfo.InvariantCulture) + "\n" + string.Join("\n", names);
}
