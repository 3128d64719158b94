using BenchmarkDotNet.Running;

namespace URWPGSim2D.Collision.Benchmarks;

/// <summary>Entry point: <c>dotnet run -c Release --project benchmarks/URWPGSim2D.Collision.Benchmarks -- --filter '*'</c>.</summary>
public static class Program
{
    /// <summary>Runs the benchmarks chosen on the command line (BenchmarkDotNet's switcher).</summary>
    /// <param name="args">BenchmarkDotNet arguments, e.g. <c>--filter *Pair*</c> or <c>--job dry</c>.</param>
    public static void Main(string[] args) => BenchmarkSwitcher.FromAssembly(typeof(Program).Assembly).Run(args);
}
