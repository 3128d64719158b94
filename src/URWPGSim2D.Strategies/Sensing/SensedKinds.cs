namespace URWPGSim2D.Strategies;

/// <summary>Which kinds of bodies a <see cref="FieldSensor"/> query looks at (combine with <c>|</c>).</summary>
[Flags]
public enum SensedKinds
{
    /// <summary>None: the query finds nothing.</summary>
    None = 0,

    /// <summary>The four field borders.</summary>
    Walls = 1,

    /// <summary>The obstacles.</summary>
    Obstacles = 2,

    /// <summary>The balls.</summary>
    Balls = 4,

    /// <summary>The fish.</summary>
    Fish = 8,

    /// <summary>What never moves: the borders and the obstacles.</summary>
    Static = Walls | Obstacles,

    /// <summary>Every body.</summary>
    All = Walls | Obstacles | Balls | Fish,
}
