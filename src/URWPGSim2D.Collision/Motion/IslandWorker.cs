namespace URWPGSim2D.Collision.Motion;

/// <summary>
/// What one thread owns while it samples a chunk of islands: its own sampler (queue, due pairs,
/// hits, remembered tests, sampled ticks), the queue entries its islands hand back, and the hits
/// they stopped at. Nothing here is shared with another worker.
/// </summary>
internal sealed class IslandWorker
{
    /// <summary>The worker's sampler.</summary>
    public PairSampler Sampler { get; } = new();

    /// <summary>Queue entries left when each island stopped, in island order.</summary>
    public QueueEntries Handoff { get; } = new();

    /// <summary>The hits each island stopped at, in island order.</summary>
    public HeldHits Held { get; } = new();

    /// <summary>Sizes the storage for a world of <paramref name="movers"/> movers.</summary>
    public void Reserve(int movers)
    {
        Sampler.Reserve(movers);
        Handoff.Reserve((8 * movers) + 256);
        Held.Reserve((2 * movers) + 64);
    }
}
