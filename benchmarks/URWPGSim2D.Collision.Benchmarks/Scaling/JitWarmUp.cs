using System.Diagnostics;
using System.Runtime;

namespace URWPGSim2D.Collision.Benchmarks.Scaling;

/// <summary>
/// Warms the JIT before a benchmark that builds its scene afresh and times a few cycles: plays
/// cycles until no method has been compiled for a second (at least 2 s, at most 30 s), so that
/// the methods a cycle runs are at their final tier, as in a long match. Without it a crowd of
/// 1,000 bodies timed over ten cycles measured several times its cost (code still at its first tier).
/// </summary>
internal static class JitWarmUp
{
    /// <summary>Calls <paramref name="step"/> (one cycle of some scene) until the JIT is still.</summary>
    public static void Until(Action step)
    {
        var clock = Stopwatch.StartNew();
        long compiled = JitInfo.GetCompiledMethodCount();
        TimeSpan still = TimeSpan.Zero;
        while (clock.Elapsed < TimeSpan.FromSeconds(30) && (clock.Elapsed < TimeSpan.FromSeconds(2) || clock.Elapsed - still < TimeSpan.FromSeconds(1)))
        {
            step();
            if (JitInfo.GetCompiledMethodCount() != compiled)
            {
                compiled = JitInfo.GetCompiledMethodCount();
                still = clock.Elapsed;
            }
        }
    }
}
