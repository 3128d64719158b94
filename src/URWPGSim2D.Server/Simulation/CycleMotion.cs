using URWPGSim2D.Collision.BroadPhase;
using URWPGSim2D.Collision.Motion;

namespace URWPGSim2D.Server.Simulation;

/// <summary>
/// The motion stage of a cycle: the world's bodies move through the 100 ms cycle in the collision
/// library's <see cref="Stepper"/> (pseudo-continuous detection: every contact at its time of
/// first contact, in time order), with the server's contact response plugged in
/// (<see cref="ContactHandler"/>). See docs/motion.md.
/// </summary>
internal sealed class CycleMotion
{
    private readonly MotionBodies _bodies;
    private readonly ContactHandler _handler;

    public CycleMotion(World world, ContactLog log, BroadPhaseKind broadPhase = BroadPhaseKind.UniformGrid)
    {
        _bodies = new MotionBodies(world, broadPhase);
        world.Bodies = _bodies;
        _handler = new ContactHandler(world, log);
    }

    /// <summary>Threads the stepper spreads a cycle's islands over (1 by default; the same match whatever the number).</summary>
    public int Threads
    {
        get => _bodies.Stepper.Threads;
        set => _bodies.Stepper.Threads = value;
    }

    /// <summary>Fewest moving bodies for which the islands are spread over threads (tests lower it).</summary>
    public int MinimumMoversForThreads
    {
        get => _bodies.Stepper.MinimumMoversForThreads;
        set => _bodies.Stepper.MinimumMoversForThreads = value;
    }

    /// <summary>Chunks of islands the last cycle ran at once (1: the calling thread alone).</summary>
    public int Chunks => _bodies.Stepper.Chunks;

    /// <summary>Distinct sample times of the last cycle.</summary>
    public int SubSteps => _bodies.Stepper.SubSteps;

    /// <summary>Contact events (times of first contact) of the last cycle.</summary>
    public int Events => _bodies.Stepper.Events;

    /// <summary>Deepest overlap of any pair (walls included) at the end of the last cycle (or settling), mm.</summary>
    public float LeftoverOverlap => _bodies.Stepper.LeftoverOverlap;

    /// <summary>Moves every body through one cycle, resolving contacts on the way.</summary>
    public void Run()
    {
        _bodies.PushAll();
        _bodies.Stepper.Step(PhysicsConstants.CycleSeconds, _handler);
        _bodies.PullAll();
    }

    /// <summary>Resolves overlaps left by a jump (balls put back at their start after a goal), without motion.</summary>
    public void Settle()
    {
        _bodies.PushAll();
        _bodies.Stepper.Settle(_handler);
        _bodies.PullAll();
    }

    /// <summary>Deepest overlap among all pairs now (no motion), mm.</summary>
    public float MeasureOverlap() => _bodies.Stepper.MeasureOverlap();
}
