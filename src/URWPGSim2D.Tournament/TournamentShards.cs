namespace URWPGSim2D.Tournament;

/// <summary>Whether a Slurm task's shard file of a tournament is done: there, of this tournament and shard, and holding a record of every match of the shard.</summary>
public static class TournamentShards
{
    /// <summary>True when the shard's file holds every one of its matches (played or forfeited).</summary>
    /// <exception cref="ResultFileException">The file holds another tournament or another shard.</exception>
    public static bool Complete(string path, TournamentHeader whole, TournamentSchedule schedule, int shard, int shards)
    {
        if (!File.Exists(path))
        {
            return false;
        }

        TournamentHeader header;
        System.Collections.Generic.List<TournamentRecord> records;
        try
        {
            (header, records, _) = TournamentFile.Read(path);
        }
        catch (ResultFileException)
        {
            return false; // not a whole file: the task plays it again
        }

        if (!header.SameTournament(whole) || header.ShardCount != shards || header.ShardIndex != shard)
        {
            string why = !header.SameTournament(whole) ? header.Difference(whole) : $"shard {header.ShardIndex}/{header.ShardCount}, not {shard}/{shards}";
            throw new ResultFileException($"{path}: belongs to another tournament or shard ({why}); use another --slurm folder or delete its shard files");
        }

        var seen = new bool[schedule.Matches.Count];
        int count = 0;
        foreach (var r in records)
        {
            if (r.Index >= 0 && r.Index < seen.Length && r.Index % shards == shard && !seen[r.Index])
            {
                seen[r.Index] = true;
                count++;
            }
        }

        int expected = (schedule.Matches.Count / shards) + (shard < schedule.Matches.Count % shards ? 1 : 0);
        return count == expected;
    }
}
