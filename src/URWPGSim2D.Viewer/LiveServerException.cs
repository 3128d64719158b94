namespace URWPGSim2D.Viewer;

/// <summary>The live view cannot listen where it was asked to (the message says where and why).</summary>
public sealed class LiveServerException(string message) : Exception(message);
