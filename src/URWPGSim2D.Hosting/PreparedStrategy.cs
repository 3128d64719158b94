namespace URWPGSim2D.Hosting;

/// <summary>A user strategy ready for strategy hosts (<see cref="StrategyResolver.Prepare"/>).</summary>
/// <param name="LoadSpec">What a host loads: an assembly's full path, optionally <c>#Namespace.Type</c> (sources: their compiled assembly).</param>
/// <param name="ReadOnly">The strategy's own files and folders, which a sandboxed host may read.</param>
public sealed record PreparedStrategy(string LoadSpec, IReadOnlyList<string> ReadOnly);
