using System.Collections.Generic;
using System.Runtime.ExceptionServices;
using System.Threading;

namespace URWPGSim2D.Collision.Motion;

/// <summary>
/// The process's island workers: background threads created once, on first need, that wait for
/// chunks of work. <see cref="Run"/> runs chunk 0 on the calling thread and chunks 1 … n − 1 on
/// workers, and returns when all are done; an exception of a chunk is thrown again on the calling
/// thread. One run at a time (motion worlds on several threads take turns). Nothing allocates per run.
/// </summary>
internal static class IslandPool
{
    private static readonly object Gate = new();
    private static readonly List<Worker> Workers = [];
    private static readonly CountdownEvent Done = new(1);
    private static IChunkWork? _work;
    private static Exception? _failure;

    /// <summary>Work split into numbered chunks that share nothing.</summary>
    internal interface IChunkWork
    {
        /// <summary>Runs one chunk.</summary>
        void RunChunk(int chunk);

        /// <summary>Counts bytes a worker's thread allocated while it ran a chunk (tests: nothing allocates on any thread).</summary>
        void CountAllocated(long bytes);
    }

    /// <summary>Runs chunks 0 … <paramref name="chunks"/> − 1 of <paramref name="work"/>, at most one per thread at once.</summary>
    public static void Run(IChunkWork work, int chunks)
    {
        if (chunks <= 1)
        {
            work.RunChunk(0);
            return;
        }

        lock (Gate)
        {
            while (Workers.Count < chunks - 1)
            {
                Workers.Add(new Worker(Workers.Count + 1));
            }

            _work = work;
            _failure = null;
            Done.Reset(chunks - 1);
            for (int c = 1; c < chunks; c++)
            {
                Workers[c - 1].Go.Release();
            }

            Exception? own = null;
            try
            {
                work.RunChunk(0);
            }
            catch (Exception e)
            {
                own = e;
            }

            Done.Wait();
            _work = null;
            Exception? failure = own ?? _failure;
            if (failure is not null)
            {
                ExceptionDispatchInfo.Capture(failure).Throw();
            }
        }
    }

    private sealed class Worker
    {
        private readonly int _chunk;

        public Worker(int chunk)
        {
            _chunk = chunk;
            var thread = new Thread(Loop) { IsBackground = true, Name = $"URWPGSim2D island worker {chunk}" };
            thread.Start();
        }

        public SemaphoreSlim Go { get; } = new(0);

        private void Loop()
        {
            while (true)
            {
                Go.Wait();
                IChunkWork work = _work!;
                long before = GC.GetAllocatedBytesForCurrentThread();
                try
                {
                    work.RunChunk(_chunk);
                }
                catch (Exception e)
                {
                    Interlocked.CompareExchange(ref _failure, e, null);
                }
                finally
                {
                    work.CountAllocated(GC.GetAllocatedBytesForCurrentThread() - before);
                    Done.Signal();
                }
            }
        }
    }
}
