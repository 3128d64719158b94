using System;

namespace URWPGSim2D.Server.Batch;

/// <summary>A result file that cannot be used; the message names the file and line.</summary>
internal sealed class ResultFileException(string message) : Exception(message);
