namespace URWPGSim2D.Strategies;

/// <summary>What kind of body of the match a <see cref="SensedBody"/> is.</summary>
public enum SensedKind
{
    /// <summary>No body (a query that found nothing).</summary>
    None,

    /// <summary>A field border: index 0 top (Z = −Width/2), 1 right (X = +Length/2), 2 bottom (Z = +Width/2), 3 left (X = −Length/2).</summary>
    Wall,

    /// <summary>An obstacle: the index of <see cref="MatchSnapshot.Obstacles"/>.</summary>
    Obstacle,

    /// <summary>A ball: the index of <see cref="MatchSnapshot.Balls"/>.</summary>
    Ball,

    /// <summary>A fish (all eight parts: body, fins, tail): the index of <see cref="MatchSnapshot.Fish"/>.</summary>
    Fish,
}
