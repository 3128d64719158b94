namespace URWPGSim2D.Tournament;

/// <summary>
/// What a tournament's folder (and shard files given to merge) already holds: the valid record
/// of each scheduled match, so that a run plays only the missing and broken ones. A record is kept
/// when its line is whole and valid JSON and its index, seed and entrants are the schedule's; a
/// forfeit is kept only while its forfeiting entrants still cannot be loaded (one that loads now
/// plays its matches). A file of the same settings but other entrants (one added, removed, or whose
/// code changed: another version) keeps the matches whose entrants are all still there in the same
/// version, each moved to its index in the new schedule (the same seed and sides); the others are played again.
/// </summary>
public static class TournamentResume
{
    /// <summary>The kept records by index, and the number of lines dropped as broken (not counting forfeits whose entrant loads now).</summary>
    /// <param name="header">The tournament asked for.</param>
    /// <param name="schedule">Its schedule.</param>
    /// <param name="files">Result files to read (missing ones are skipped).</param>
    /// <param name="errors">Per entrant, why it cannot be loaded now, or null.</param>
    /// <exception cref="ResultFileException">A file is not a tournament's or holds another tournament: one line naming it.</exception>
    public static (SortedDictionary<int, TournamentRecord> Records, int Dropped) Gather(TournamentHeader header, TournamentSchedule schedule, IEnumerable<string> files, IReadOnlyList<string?> errors)
    {
        var (records, dropped, _) = GatherAll(header, schedule, files, errors);
        return (records, dropped);
    }

    /// <summary>
    /// As <see cref="Gather"/>, and the records of a file of other entrants: how many were left to be
    /// played again (an entrant changed or left), and where each kept one moved (old index → new
    /// index, only when the entrants differ; null otherwise).
    /// </summary>
    public static (SortedDictionary<int, TournamentRecord> Records, int Dropped, Remap? Remapped) GatherAll(TournamentHeader header, TournamentSchedule schedule, IEnumerable<string> files, IReadOnlyList<string?> errors)
    {
        var kept = new SortedDictionary<int, TournamentRecord>();
        int dropped = 0;
        Remap? remap = null;
        foreach (string file in files)
        {
            if (!File.Exists(file))
            {
                continue;
            }

            var (found, read, broken) = TournamentFile.Read(file);
            if (!found.SameSettings(header))
            {
                throw new ResultFileException($"{file}: holds another tournament ({found.Difference(header)})");
            }

            dropped += broken;
            IEnumerable<TournamentRecord> records = read;
            if (!found.SameTournament(header))
            {
                remap ??= new Remap(new Dictionary<int, int>(), 0);
                var (moved, changed) = Move(found, header, schedule, read, remap.Moved);
                records = moved;
                remap = remap with { Changed = remap.Changed + changed };
            }

            foreach (var r in records)
            {
                if (!Fits(r, schedule, header))
                {
                    dropped++;
                }
                else if (Stands(r, schedule, errors))
                {
                    kept[r.Index] = r;
                }
            }
        }

        return (kept, dropped, remap);
    }

    /// <summary>What became of the records of a file of other entrants.</summary>
    /// <param name="Moved">Old index → new index of each record kept.</param>
    /// <param name="Changed">Records left to be played again: one of their entrants changed its code or is no longer in the tournament.</param>
    public sealed record Remap(Dictionary<int, int> Moved, int Changed);

    // The records of another entrant list that still hold, at their index in this schedule.
    private static (List<TournamentRecord> Records, int Changed) Move(TournamentHeader found, TournamentHeader header, TournamentSchedule schedule, IReadOnlyList<TournamentRecord> records, Dictionary<int, int> moved)
    {
        var now = new Dictionary<string, Entrant>(System.StringComparer.Ordinal);
        foreach (var e in header.Entrants)
        {
            now[e.Name] = e;
        }

        var then = new Dictionary<string, Entrant>(System.StringComparer.Ordinal);
        foreach (var e in found.Entrants)
        {
            then[e.Name] = e;
        }

        var index = new Dictionary<string, int>(System.StringComparer.Ordinal);
        foreach (var m in schedule.Matches)
        {
            index[Key(m.Seed, m.Sides.Select(s => header.Entrants[s].Name))] = m.Index;
        }

        var kept = new List<TournamentRecord>(records.Count);
        int changed = 0;
        foreach (var r in records)
        {
            bool same = r.Entrants.All(n => now.TryGetValue(n, out var e) && then.TryGetValue(n, out var was) && e == was);
            if (same && index.TryGetValue(Key(r.Seed, r.Entrants), out int to))
            {
                moved[r.Index] = to;
                kept.Add(r with { Index = to, Result = r.Result is { } result ? result with { Index = to } : null });
            }
            else
            {
                changed++;
            }
        }

        return (kept, changed);
    }

    private static string Key(ulong seed, IEnumerable<string> names) => seed.ToString(System.Globalization.CultureInfo.InvariantCulture) + "\n" + string.Join("\n", names);

    /// <summary>Whether a record is the scheduled match's (index, seed and entrants).</summary>
    public static bool Fits(TournamentRecord r, TournamentSchedule schedule, TournamentHeader header)
    {
        if (r.Index < 0 || r.Index >= schedule.Matches.Count)
        {
            return false;
        }

        var m = schedule.Matches[r.Index];
        if (r.Seed != m.Seed || r.Entrants.Count != m.Sides.Count || (r.Result is { } result && result.Seed != m.Seed))
        {
            return false;
        }

        for (int t = 0; t < m.Sides.Count; t++)
        {
            if (r.Entrants[t] != header.Entrants[m.Sides[t]].Name)
            {
                return false;
            }
        }

        foreach (int team in r.Forfeits)
        {
            if (team < 0 || team >= m.Sides.Count)
            {
                return false;
            }
        }

        return true;
    }

    /// <summary>Whether a fitting record still stands: a played match and a match that failed inside the server always, a forfeit while its entrants still cannot be loaded.</summary>
    public static bool Stands(TournamentRecord r, TournamentSchedule schedule, IReadOnlyList<string?> errors)
    {
        if (r.Failed)
        {
            return true; // the match failed inside the server: playing it again would fail again
        }

        foreach (int team in r.Forfeits)
        {
            if (errors[schedule.Matches[r.Index].Sides[team]] is null)
            {
                return false; // the entrant loads now: play the match
            }
        }

        return true;
    }
}
