using System;

namespace URWPGSim2D.Server.Strategies;

/// <summary>A user strategy could not be loaded; the message is one line for the command line.</summary>
/// <param name="message">What went wrong.</param>
public sealed class StrategyLoadException(string message) : Exception(message);
