namespace URWPGSim2D.Protocol;

/// <summary>The server's last message: the match is over.</summary>
/// <param name="Cycle">Cycles played.</param>
/// <param name="Goals0">Team 0's score.</param>
/// <param name="Goals1">Team 1's score.</param>
/// <param name="Faults">Faults charged to the client's team.</param>
internal sealed record EndMessage(int Cycle, int Goals0, int Goals1, int Faults);
