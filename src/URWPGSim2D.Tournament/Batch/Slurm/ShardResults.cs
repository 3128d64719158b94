namespace URWPGSim2D.Tournament.Batch.Slurm;

/// <summary>
/// The result files of a Slurm batch's shards in its folder (<c>shard-I.jsonl</c>) and which of
/// them still have to be played: a shard is done when its file is there and holds every match of
/// the shard. A task writes its file through <c>.partial</c> and renames it at the end, so a task
/// that failed or was stopped leaves no file (at most a <c>.partial</c>) and is played again.
/// </summary>
public static class ShardResults
{
    /// <summary>The result file of shard <paramref name="shard"/>, in the batch's folder.</summary>
    public static string FileName(int shard) => string.Create(CultureInfo.InvariantCulture, $"shard-{shard}.jsonl");

    /// <summary>The shards 0 … <paramref name="shards"/> − 1 whose result file in <paramref name="folder"/> is missing or incomplete, in increasing order.</summary>
    /// <param name="folder">The batch's folder (need not exist).</param>
    /// <param name="whole">The header of the whole batch (shard 0 of 1).</param>
    /// <param name="shards">The number of shards.</param>
    /// <exception cref="ResultFileException">A file there belongs to another batch or to another shard: one line naming the file.</exception>
    public static List<int> ToPlay(string folder, BatchHeader whole, int shards)
    {
        var play = new List<int>();
        for (int i = 0; i < shards; i++)
        {
            string path = Path.Combine(folder, FileName(i));
            if (!File.Exists(path))
            {
                play.Add(i);
                continue;
            }

            BatchHeader header;
            List<MatchResult> results;
            try
            {
                (header, results) = ResultFile.Read(path);
            }
            catch (ResultFileException)
            {
                play.Add(i); // not a whole result file: play the shard again, which replaces it
                continue;
            }

            if (header.Whole != whole || header.ShardCount != shards)
            {
                string why = header.ShardCount != shards
                    ? $"{header.ShardCount} vs {shards} shards"
                    : BatchHeader.Difference(header.Whole, whole);
                throw new ResultFileException($"{path}: belongs to another batch ({why}); use another --slurm folder or delete its shard files");
            }

            if (header.ShardIndex != i)
            {
                throw new ResultFileException($"{path}: holds shard {header.ShardIndex}/{shards}, not {i}/{shards}");
            }

            if (!Complete(header, results))
            {
                play.Add(i);
            }
        }

        return play;
    }

    // Every match of the shard, once, in order.
    private static bool Complete(BatchHeader header, List<MatchResult> results)
    {
        if (results.Count != header.ShardMatches)
        {
            return false;
        }

        for (int k = 0; k < results.Count; k++)
        {
            if (results[k].Index != header.ShardIndex + (k * header.ShardCount))
            {
                return false;
            }
        }

        return true;
    }
}
