namespace URWPGSim2D.Engine.Simulation;

/// <summary>
/// The tag the match gives each of its bodies in the motion world (<c>MotionWorld.SetTag</c>): what
/// the body is (a fish, a ball, a static body, the walls) and its index in the world's array of
/// that kind, so that a contact's bodies are found from their tags, not from where their ids fall.
/// </summary>
internal static class BodyTag
{
    private const int RoleShift = 24;
    private const int IndexMask = (1 << RoleShift) - 1;

    /// <summary>The walls' tag.</summary>
    public const int Walls = (int)BodyRole.Walls << RoleShift;

    /// <summary>Fish <paramref name="index"/>'s tag.</summary>
    public static int Fish(int index) => ((int)BodyRole.Fish << RoleShift) | index;

    /// <summary>Ball <paramref name="index"/>'s tag.</summary>
    public static int Ball(int index) => ((int)BodyRole.Ball << RoleShift) | index;

    /// <summary>Static body <paramref name="index"/>'s tag (<see cref="World.Statics"/>: obstacles, then goal blocks).</summary>
    public static int Static(int index) => ((int)BodyRole.Static << RoleShift) | index;

    /// <summary>What a tagged body is.</summary>
    public static BodyRole RoleOf(int tag) => (BodyRole)(tag >> RoleShift);

    /// <summary>A tagged body's index in the world's array of its kind (0 for the walls).</summary>
    public static int IndexOf(int tag) => tag & IndexMask;
}

/// <summary>What a body of the match is (see <see cref="BodyTag"/>).</summary>
internal enum BodyRole
{
    /// <summary>Not tagged.</summary>
    None,

    /// <summary>A fish.</summary>
    Fish,

    /// <summary>A ball.</summary>
    Ball,

    /// <summary>An obstacle or a goal block.</summary>
    Static,

    /// <summary>The pool's walls.</summary>
    Walls,
}
