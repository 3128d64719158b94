namespace URWPGSim2D.Collision.Benchmarks.Diagnostics;

/// <summary>
/// A check of the benchmark program itself, not a measurement: with the environment variable
/// <c>URWPGSIM2D_BENCHMARK_SELFTEST_THROW=1</c> its benchmark throws on every call, and the
/// program must exit 1 (CI's <c>.ci/smoke</c> runs it so, in process). Without the variable it
/// measures an empty call.
/// </summary>
public class SelfTestBenchmarks
{
    private readonly bool _throw = Environment.GetEnvironmentVariable("URWPGSIM2D_BENCHMARK_SELFTEST_THROW") == "1";

    /// <summary>Throws when asked to, else does nothing.</summary>
    [Benchmark]
    public int ThrowWhenAsked() => _throw ? throw new InvalidOperationException("self-test: this benchmark throws on purpose") : 0;
}
