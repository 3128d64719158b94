using BenchmarkDotNet.Configs;
using BenchmarkDotNet.Diagnosers;

namespace URWPGSim2D.Collision.Benchmarks.Reporting;

/// <summary>
/// The configuration of every benchmark class measured against a frozen baseline: memory
/// diagnoser, the median column, one baseline per category (<c>[BenchmarkCategory]</c>) and
/// parameter set, and the <see cref="SpeedUpColumn"/>. The job comes from the command line
/// (<c>benchmarks/run-all.sh</c> uses the short job).
/// </summary>
public sealed class BaselineConfig : ManualConfig
{
    /// <summary>Creates the configuration.</summary>
    public BaselineConfig()
    {
        AddDiagnoser(MemoryDiagnoser.Default);
        AddColumn(BenchmarkDotNet.Columns.StatisticColumn.Median);
        AddColumn(new SpeedUpColumn());
        AddLogicalGroupRules(BenchmarkLogicalGroupRule.ByCategory, BenchmarkLogicalGroupRule.ByParams);
        HideColumns(BenchmarkDotNet.Columns.Column.Ratio, BenchmarkDotNet.Columns.Column.RatioSD, BenchmarkDotNet.Columns.Column.AllocRatio);
    }
}
