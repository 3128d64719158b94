using URWPGSim2D.Collision.Motion;

namespace URWPGSim2D.Engine.Simulation;

/// <summary>
/// The motion stage of a cycle: the world's bodies move through the 100 ms cycle in the motion
/// world (the collision library's <see cref="MotionWorld"/>: pseudo-continuous detection, every first
/// contact at its time of first contact, in time order; touching pairs answered together on
/// <see cref="HeldSubSteps"/> sub-steps), with the server's contact response plugged in
/// (<see cref="ContactHandler"/>). See docs/motion.md.
/// </summary>
public sealed class CycleMotion
{
    /// <summary>
    /// The sub-steps of a cycle on which a match answers its touching pairs together (a fish
    /// pressing a ball, a ball held against a wall): 2, every 50 ms (see
    /// <see cref="MotionWorld.HeldSubSteps"/>). Of 2 and 4, both as faithful on the head-on push
    /// (docs/motion.md, held contacts), 2 is the cheaper in a crowd.
    /// </summary>
    public static int HeldSubSteps => 2;

    private readonly World _world;
    private readonly ContactHandler _handler;

    /// <summary>Creates the motion stage of <paramref name="world"/>, recording contacts in <paramref name="log"/>.</summary>
    /// <param name="world">The match's world.</param>
    /// <param name="log">Where each cycle's contacts are recorded.</param>
    public CycleMotion(World world, ContactLog log)
    {
        _world = world;
        _handler = new ContactHandler(world, log);
        world.Motion.HeldSubSteps = HeldSubSteps;
    }

    /// <summary>Threads the motion world spreads a cycle's islands over (1 by default; the same match whatever the number).</summary>
    public int Threads
    {
        get => _world.Motion.Threads;
        set => _world.Motion.Threads = value;
    }

    /// <summary>Fewest moving bodies for which the islands are spread over threads (tests lower it).</summary>
    public int MinimumMoversForThreads
    {
        get => _world.Motion.MinimumMoversForThreads;
        set => _world.Motion.MinimumMoversForThreads = value;
    }

    /// <summary>Chunks of islands the last cycle ran at once (1: the calling thread alone).</summary>
    public int Chunks => _world.Motion.Chunks;

    /// <summary>Distinct sample times of the last cycle.</summary>
    public int SubSteps => _world.Motion.SubSteps;

    /// <summary>Contact events (times of first contact) of the last cycle.</summary>
    public int Events => _world.Motion.Events;

    /// <summary>Deepest overlap of any pair (walls included) at the end of the last cycle (or settling), mm.</summary>
    public float LeftoverOverlap => _world.Motion.LeftoverOverlap;

    /// <summary>
    /// Forgets what the stage remembers of the cycles played (the motion world's touches, the
    /// response's contacts of the cycle), for a match put back to cycle 0 in place: it then plays
    /// what a new stage plays.
    /// </summary>
    internal void Restart()
    {
        _world.Motion.ForgetTouches();
        _handler.Restart();
    }

    /// <summary>Moves every body through one cycle, resolving contacts on the way.</summary>
    public void Run()
    {
        _world.Motion.Step(PhysicsConstants.CycleSeconds, _handler);
    }

    /// <summary>Resolves overlaps left by a jump (balls put back at their start after a goal), without motion.</summary>
    public void Settle()
    {
        _world.Motion.Settle(_handler);
    }

    /// <summary>Deepest overlap among all pairs now (no motion), mm.</summary>
    public float MeasureOverlap() => _world.Motion.MeasureOverlap();
}
