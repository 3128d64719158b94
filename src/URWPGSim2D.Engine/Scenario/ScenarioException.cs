namespace URWPGSim2D.Engine.Scenario;

/// <summary>
/// A scenario is invalid. The message is one line: the JSON path and the problem, e.g.
/// <c>balls[2].radius: must be > 0, got -5</c>.
/// </summary>
public sealed class ScenarioException : Exception
{
    /// <summary>Creates the error for a JSON path.</summary>
    /// <param name="path">JSON path such as <c>balls[2].radius</c> (empty for the whole document).</param>
    /// <param name="problem">What is wrong.</param>
    public ScenarioException(string path, string problem)
        : base(path.Length == 0 ? problem : $"{path}: {problem}")
    {
        Path = path;
        Problem = problem;
    }

    /// <summary>The problem without the path.</summary>
    public string Problem { get; }

    /// <summary>The JSON path of the offending value.</summary>
    public string Path { get; }
}
