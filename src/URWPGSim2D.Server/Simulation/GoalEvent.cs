namespace URWPGSim2D.Server.Simulation;

/// <summary>A goal: the cycle it was scored in, the ball and the scoring team.</summary>
/// <param name="Cycle">Cycle number (1-based).</param>
/// <param name="Ball">Ball index.</param>
/// <param name="Team">Scoring team.</param>
internal readonly record struct GoalEvent(int Cycle, int Ball, int Team);
