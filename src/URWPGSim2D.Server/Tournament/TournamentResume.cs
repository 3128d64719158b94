using System.Collections.Generic;
using System.IO;
using URWPGSim2D.Server.Batch;

namespace URWPGSim2D.Server.Tournament;

/// <summary>
/// What a tournament's folder (and shard files given to merge) already holds: the valid record
/// of each scheduled match, so that a run plays only the missing and broken ones. A record is kept
/// when its line is whole and valid JSON and its index, seed and entrants are the schedule's; a
/// forfeit is kept only while its forfeiting entrants still cannot be loaded (one that loads now
/// plays its matches).
/// </summary>
internal static class TournamentResume
{
    /// <summary>The kept records by index, and the number of lines dropped as broken (not counting forfeits whose entrant loads now).</summary>
    /// <param name="header">The tournament asked for.</param>
    /// <param name="schedule">Its schedule.</param>
    /// <param name="files">Result files to read (missing ones are skipped).</param>
    /// <param name="errors">Per entrant, why it cannot be loaded now, or null.</param>
    /// <exception cref="ResultFileException">A file is not a tournament's or holds another tournament: one line naming it.</exception>
    public static (SortedDictionary<int, TournamentRecord> Records, int Dropped) Gather(TournamentHeader header, TournamentSchedule schedule, IEnumerable<string> files, IReadOnlyList<string?> errors)
    {
        var kept = new SortedDictionary<int, TournamentRecord>();
        int dropped = 0;
        foreach (string file in files)
        {
            if (!File.Exists(file))
            {
                continue;
            }

            var (found, records, broken) = TournamentFile.Read(file);
            if (!found.SameTournament(header))
            {
                throw new ResultFileException($"{file}: holds another tournament ({found.Difference(header)})");
            }

            dropped += broken;
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

        return (kept, dropped);
    }

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
