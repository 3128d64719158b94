namespace URWPGSim2D.Engine.Items;

/// <summary>The obstacles of a layout given as rectangles at heading 0 (centre, length along x, width along z), in order.</summary>
internal static class AxisRectangles
{
    /// <summary>The scenario's obstacle definitions of <paramref name="rectangles"/>, in the same order (obstacle i is rectangle i).</summary>
    public static List<ObstacleDefinition> Obstacles(ReadOnlySpan<(Vector2 Centre, float Length, float Width)> rectangles)
    {
        var obstacles = new List<ObstacleDefinition>(rectangles.Length);
        foreach (var (centre, length, width) in rectangles)
        {
            obstacles.Add(new ObstacleDefinition(ObstacleKind.Rectangle, centre, length, width, 0f, 0f));
        }

        return obstacles;
    }

    /// <summary>
    /// Adds to <paramref name="obstacles"/> a <paramref name="length"/> by <paramref name="width"/>
    /// rectangle at each of <paramref name="centres"/>, in order; returns <paramref name="obstacles"/>.
    /// </summary>
    public static List<ObstacleDefinition> AddAt(List<ObstacleDefinition> obstacles, ReadOnlySpan<Vector2> centres, float length, float width)
    {
        foreach (var centre in centres)
        {
            obstacles.Add(new ObstacleDefinition(ObstacleKind.Rectangle, centre, length, width, 0f, 0f));
        }

        return obstacles;
    }
}
