namespace URWPGSim2D.Strategies;

/// <summary>The two obstacle shapes of the original.</summary>
public enum ObstacleKind
{
    /// <summary>A rectangle: centre, length along its heading, width across it.</summary>
    Rectangle,

    /// <summary>A disc: centre and radius.</summary>
    Round,
}
