namespace URWPGSim2D.Common;

/// <summary>The kinds of contact the original names.</summary>
public enum CollisionType
{
    /// <summary>No contact.</summary>
    NONE = 0,

    /// <summary>Fish against fish.</summary>
    FISH_FISH,

    /// <summary>Fish against ball.</summary>
    FISH_BALL,

    /// <summary>Fish against a pool wall.</summary>
    FISH_POOL,

    /// <summary>Fish against a static obstacle.</summary>
    FISH_OBSTACLE,

    /// <summary>Fish against a channel.</summary>
    FISH_CHANNEL,

    /// <summary>Ball against a pool wall.</summary>
    BALL_POOL,

    /// <summary>Ball against a static obstacle.</summary>
    BALL_OBSTACLE,

    /// <summary>Ball against a channel.</summary>
    BALL_CHANNEL,
}
