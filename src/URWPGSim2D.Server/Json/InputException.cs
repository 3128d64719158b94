namespace URWPGSim2D.Server.Json;

/// <summary>
/// Bad input data: reported as the single stderr line <c>PATH: MESSAGE</c>, exit code 2.
/// <see cref="Path"/> names the offending place in the input the way a user reads it
/// (<c>pairs[12].b.vertices</c>) or the input file that could not be read.
/// </summary>
internal sealed class InputException : Exception
{
    /// <summary>Creates the error.</summary>
    /// <param name="path">Where in the input the problem is, e.g. <c>pairs[3].a.radius</c>.</param>
    /// <param name="message">What is wrong, one line, e.g. <c>must be &gt; 0, got -5</c>.</param>
    public InputException(string path, string message)
        : base(message)
    {
        Path = path;
    }

    /// <summary>Where in the input the problem is.</summary>
    public string Path { get; }

    /// <summary>The line written to stderr: <c>PATH: MESSAGE</c>.</summary>
    public string Line => $"{Path}: {Message}";
}
