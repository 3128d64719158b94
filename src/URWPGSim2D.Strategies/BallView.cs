namespace URWPGSim2D.Strategies;

/// <summary>What a strategy sees of one ball (mm, mm/s; X = world X, Y = world Z).</summary>
/// <param name="Index">Ball index (the trace's ballN).</param>
/// <param name="Position">Centre, mm.</param>
/// <param name="Velocity">Velocity, mm/s.</param>
/// <param name="Radius">Radius, mm.</param>
public readonly record struct BallView(int Index, Vector2 Position, Vector2 Velocity, float Radius);
