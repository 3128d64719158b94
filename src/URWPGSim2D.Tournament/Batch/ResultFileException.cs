namespace URWPGSim2D.Tournament.Batch;

/// <summary>A result file that cannot be used; the message names the file and line.</summary>
public sealed class ResultFileException(string message) : Exception(message);
