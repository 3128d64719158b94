namespace URWPGSim2D.Viewer;

/// <summary>The answer to a live view's control request: an HTTP status and a plain-text body (lines; empty for none).</summary>
/// <param name="Status">204 done with nothing to say, 200 done with lines to show, 400 refused (the lines say why).</param>
/// <param name="Text">The lines, each ending in a newline.</param>
public readonly record struct LiveReply(int Status, string Text)
{
    /// <summary>Done, nothing to say.</summary>
    public static LiveReply Done { get; } = new(204, string.Empty);

    /// <summary>Refused: <paramref name="lines"/> say why (the first is the one-line reason).</summary>
    public static LiveReply Refused(params string[] lines) => new(400, string.Concat(System.Linq.Enumerable.Select(lines, l => l + "\n")));
}
