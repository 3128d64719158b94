namespace URWPGSim2D.Viewer;

/// <summary>A trace line the viewer cannot use; the message names the line's field and what is wrong.</summary>
public sealed class TraceFormatException(string message) : Exception(message);
