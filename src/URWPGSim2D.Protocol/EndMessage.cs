namespace URWPGSim2D.Protocol;

/// <summary>The server's last message: the match is over.</summary>
/// <param name="Cycle">Cycles played.</param>
/// <param name="Goals">Each team's score (2 entries, or 4 in a four-team item).</param>
/// <param name="Faults">Faults charged to the client's team.</param>
public sealed record EndMessage(int Cycle, int[] Goals, int Faults);
