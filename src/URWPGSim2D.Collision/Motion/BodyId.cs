using System.Threading;

namespace URWPGSim2D.Collision.Motion;

/// <summary>
/// A body of a <see cref="MotionWorld"/>, as the <c>Add…</c> methods return it: its number in the
/// motion world (<see cref="Index"/>), whether it is static, which motion world made it, and its
/// generation (which bodies of that motion world, since it was last cleared). Every method that
/// takes a body checks that the id is one of that motion world's bodies now, so an id from another
/// motion world, a stale one (its body removed by <see cref="MotionWorld.Clear"/>) or
/// <c>default(BodyId)</c> is refused by name instead of naming some other body. What a body is
/// in the caller's game (a fish, a ball and its index) is its tag (<see cref="MotionWorld.SetTag"/>),
/// not where its id falls.
/// </summary>
public readonly struct BodyId : IEquatable<BodyId>
{
    private static int s_lastWorld;

    private readonly int _index;
    private readonly int _world;
    private readonly int _generation;
    private readonly bool _static;

    internal BodyId(int index, int world, int generation, bool isStatic)
    {
        _index = index;
        _world = world;
        _generation = generation;
        _static = isStatic;
    }

    /// <summary>The body's number in its motion world: 0 … <see cref="MotionWorld.BodyCount"/> − 1, in the order bodies were added (−1 for <c>default</c>).</summary>
    public int Index => IsNull ? -1 : _index;

    /// <summary>Whether the body never moves: a static body or the walls.</summary>
    public bool IsStatic => _static;

    /// <summary>Whether the id names no body (<c>default(BodyId)</c>).</summary>
    public bool IsNull => _world == 0;

    /// <summary>The number of the motion world that made the id (never 0).</summary>
    internal int World => _world;

    /// <summary>Which bodies of the motion world the id belongs to: 1 at first, one more after each <see cref="MotionWorld.Clear"/>.</summary>
    internal int Generation => _generation;

    /// <summary>Whether two ids name the same body of the same motion world.</summary>
    /// <param name="left">The first id.</param>
    /// <param name="right">The second id.</param>
    /// <returns>True when equal.</returns>
    public static bool operator ==(BodyId left, BodyId right) => left.Equals(right);

    /// <summary>Whether two ids name different bodies.</summary>
    /// <param name="left">The first id.</param>
    /// <param name="right">The second id.</param>
    /// <returns>True when different.</returns>
    public static bool operator !=(BodyId left, BodyId right) => !left.Equals(right);

    /// <inheritdoc />
    public bool Equals(BodyId other) =>
        _index == other._index && _world == other._world && _generation == other._generation && _static == other._static;

    /// <inheritdoc />
    public override bool Equals(object? obj) => obj is BodyId other && Equals(other);

    /// <inheritdoc />
    public override int GetHashCode() => HashCode.Combine(_index, _world, _generation);

    /// <summary>"body 3", "static body 5", or "no body".</summary>
    /// <returns>The text.</returns>
    public override string ToString() => IsNull ? "no body" : (_static ? "static body " : "body ") + _index;

    /// <summary>A new motion world's number, distinct from every other motion world's of the process.</summary>
    internal static int NextWorld()
    {
        int world = Interlocked.Increment(ref s_lastWorld);
        return world != 0 ? world : Interlocked.Increment(ref s_lastWorld);
    }
}
