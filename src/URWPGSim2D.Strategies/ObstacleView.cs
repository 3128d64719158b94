namespace URWPGSim2D.Strategies;

/// <summary>What a strategy sees of one obstacle (mm, rad; X = world X, Y = world Z).</summary>
/// <param name="Index">Obstacle index (the trace's obstacleN).</param>
/// <param name="Kind">Rectangle or round.</param>
/// <param name="Center">Centre, mm.</param>
/// <param name="Length">Rectangle length along its heading, mm (2·radius for a round one).</param>
/// <param name="Width">Rectangle width, mm (2·radius for a round one).</param>
/// <param name="Heading">Rectangle direction, rad.</param>
/// <param name="Radius">Round obstacle radius, mm (0 for a rectangle).</param>
public readonly record struct ObstacleView(int Index, ObstacleKind Kind, Vector2 Center, float Length, float Width, float Heading, float Radius);
