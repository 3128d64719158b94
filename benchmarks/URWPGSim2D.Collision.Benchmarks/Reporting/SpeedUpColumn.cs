using System.Globalization;
using BenchmarkDotNet.Columns;
using BenchmarkDotNet.Reports;
using BenchmarkDotNet.Running;

namespace URWPGSim2D.Collision.Benchmarks.Reporting;

/// <summary>
/// "Speed-up": the median of the case's baseline (the frozen copy of the code as it was before
/// issue 10, measured in the same run, same category and parameters) divided by the case's own
/// median. Medians, not means: the machine is shared and a few slow iterations move a mean far
/// more than a median. Above 1 the case is faster than its baseline; the baseline row reads 1.00.
/// </summary>
public sealed class SpeedUpColumn : IColumn
{
    /// <inheritdoc/>
    public string Id => nameof(SpeedUpColumn);

    /// <inheritdoc/>
    public string ColumnName => "Speed-up (median)";

    /// <inheritdoc/>
    public bool AlwaysShow => true;

    /// <inheritdoc/>
    public ColumnCategory Category => ColumnCategory.Baseline;

    /// <inheritdoc/>
    public int PriorityInCategory => 0;

    /// <inheritdoc/>
    public bool IsNumeric => true;

    /// <inheritdoc/>
    public UnitType UnitType => UnitType.Dimensionless;

    /// <inheritdoc/>
    public string Legend => "Median of the frozen baseline in the same group divided by this case's median (above 1: faster)";

    /// <inheritdoc/>
    public bool IsDefault(Summary summary, BenchmarkCase benchmarkCase) => false;

    /// <inheritdoc/>
    public bool IsAvailable(Summary summary) => true;

    /// <inheritdoc/>
    public string GetValue(Summary summary, BenchmarkCase benchmarkCase) => GetValue(summary, benchmarkCase, SummaryStyle.Default);

    /// <inheritdoc/>
    public string GetValue(Summary summary, BenchmarkCase benchmarkCase, SummaryStyle style)
    {
        double? ratio = SpeedUp(summary, benchmarkCase);
        return ratio is { } r ? r.ToString("0.00", CultureInfo.InvariantCulture) + "×" : "?";
    }

    /// <summary>Baseline median / this median, or null when either has no result or there is no baseline.</summary>
    /// <param name="summary">The run's summary.</param>
    /// <param name="benchmarkCase">The case.</param>
    /// <returns>The speed-up, or null.</returns>
    public static double? SpeedUp(Summary summary, BenchmarkCase benchmarkCase)
    {
        var baseline = summary.GetBaseline(summary.GetLogicalGroupKey(benchmarkCase));
        double? own = summary[benchmarkCase]?.ResultStatistics?.Median;
        double? reference = baseline is null ? null : summary[baseline]?.ResultStatistics?.Median;
        return own is > 0 && reference is > 0 ? reference / own : null;
    }
}
