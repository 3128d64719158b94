using System.Threading;
using System.Runtime.ExceptionServices;
using URWPGSim2D.Engine.Matches;
using URWPGSim2D.Engine.Simulation;

namespace URWPGSim2D.Tournament.Batch;

/// <summary>
/// Plays the matches of one shard of a batch on several threads. Match j (the shard's matches are
/// j = I, I + K, I + 2K, … below N) is built with seed FirstSeed + j and played alone by one thread,
/// so its result depends only on j: not on the thread count, the order the threads finish in, or
/// the shard. Results are reported in match order as soon as every earlier one is done. A match that
/// fails inside the server has a line all the same, with the reason (<see cref="MatchResult.Failed"/>).
/// </summary>
public static class BatchRunner
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
        int next = -1;
        int reported = 0;
        var gate = new object();
        Exception? failure = null;

        // Each worker takes the next match as soon as it is free (one match at a time, so the load
        // stays even however long the matches are).
        void Work()
        {
            try
            {
                int position;
                while ((position = Interlocked.Increment(ref next)) < count && Volatile.Read(ref failure) is null)
                {
                    int index = header.ShardIndex + (position * header.ShardCount);
                    ulong seed = header.FirstSeed + (ulong)index;
                    MatchResult result;
                    try
                    {
                        result = Play(build(seed), index, seed, header.Cycles);
                    }
                    catch (Exception e) when (e is not OutOfMemoryException and not Hosting.StrategyLoadException)
                    {
                        result = MatchResult.FailedMatch(index, seed, e); // every match has its line
                    }

                    Volatile.Write(ref results[position], result);
                    lock (gate)
                    {
                        while (reported < count && results[reported] is { } done)
                        {
                            report(done);
                            reported++;
                        }
                    }
                }
            }
            catch (Exception e)
            {
                Interlocked.CompareExchange(ref failure, e, null);
            }
        }

        int workers = Math.Clamp(threads, 1, Math.Max(1, count));
        var pool = new Thread[workers - 1];
        for (int w = 0; w < pool.Length; w++)
        {
            pool[w] = new Thread(Work) { IsBackground = true, Name = $"batch worker {w + 1}" };
            pool[w].Start();
        }

        Work();
        foreach (var thread in pool)
        {
            thread.Join();
        }

        if (failure is not null)
        {
            ExceptionDispatchInfo.Capture(failure).Throw();
        }

        return results;
    }

    private static MatchResult Play(Match match, int index, ulong seed, int cycles)
    {
        using var loop = new MatchLoop(match, cycles);
        loop.Play();
        return MatchResult.Of(index, seed, match);
    }
}
