using System;
using System.Threading;
using System.Threading.Tasks;
using URWPGSim2D.Server.Simulation;

namespace URWPGSim2D.Server.Batch;

/// <summary>
/// Plays the matches of one shard of a batch on several threads. Match j (the shard's matches are
/// j = I, I + K, I + 2K, … below N) is built with seed FirstSeed + j and played alone by one thread,
/// so its result depends only on j: not on the thread count, the order the threads finish in, or
/// the shard. Results are reported in match order as soon as every earlier one is done.
/// </summary>
internal static class BatchRunner
{
    /// <summary>Plays the shard; returns its results in match order.</summary>
    /// <param name="header">The batch and the shard to play.</param>
    /// <param name="threads">Matches played at once, ≥ 1.</param>
    /// <param name="build">Builds match j's match from its seed.</param>
    /// <param name="report">Called in match order, one result at a time (under a lock).</param>
    public static MatchResult[] Run(BatchHeader header, int threads, Func<ulong, Match> build, Action<MatchResult> report)
    {
        int count = header.ShardMatches;
        var results = new MatchResult[count];
        int reported = 0;
        var gate = new object();
        var options = new ParallelOptions { MaxDegreeOfParallelism = Math.Max(1, threads) };
        Parallel.For(0, count, options, position =>
        {
            int index = header.ShardIndex + (position * header.ShardCount);
            ulong seed = header.FirstSeed + (ulong)index;
            Match match = build(seed);
            try
            {
                for (int k = 0; k < header.Cycles; k++)
                {
                    match.Step();
                }
            }
            finally
            {
                match.Strategies.Stop();
            }

            Volatile.Write(ref results[position], MatchResult.Of(index, seed, match));
            lock (gate)
            {
                while (reported < count && results[reported] is { } done)
                {
                    report(done);
                    reported++;
                }
            }
        });

        return results;
    }
}
