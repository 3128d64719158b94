using System;

namespace URWPGSim2D.Server.Viewer;

/// <summary>A trace line the viewer cannot use; the message names the line's field and what is wrong.</summary>
internal sealed class TraceFormatException(string message) : Exception(message);
