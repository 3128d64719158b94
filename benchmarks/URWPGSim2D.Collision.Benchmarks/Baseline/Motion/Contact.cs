using URWPGSim2D.Collision.Fish;

namespace URWPGSim2D.Collision.Benchmarks.Baseline.Motion;

/// <summary>One contact the <see cref="Stepper"/> reports: two bodies overlapping at a time of the step.</summary>
internal readonly struct Contact
{
    internal Contact(int bodyA, int bodyB, in Hit hit, double time)
    {
        BodyA = bodyA;
        BodyB = bodyB;
        Result = hit.Result;
        PartA = hit.PartA < 0 ? null : (FishPart)hit.PartA;
        PartB = hit.PartB < 0 ? null : (FishPart)hit.PartB;
        Time = time;
    }

    /// <summary>The first body (always a moving one): <see cref="Result"/>'s translation moves it out of <see cref="BodyB"/>.</summary>
    public int BodyA { get; }

    /// <summary>The second body: moving, static or the walls.</summary>
    public int BodyB { get; }

    /// <summary>The overlap: minimum translation of A, unit normal from B toward A, action point (X–Z plane, mm).</summary>
    public CollisionDetectionResult Result { get; }

    /// <summary>The leaf of A in contact when A is a fish, else null.</summary>
    public FishPart? PartA { get; }

    /// <summary>The leaf of B in contact when B is a fish, else null.</summary>
    public FishPart? PartB { get; }

    /// <summary>When in the step, as a fraction 0 … 1 of its duration (the time of first contact).</summary>
    public double Time { get; }

    /// <summary>Whether the bodies overlap (false for "no contact").</summary>
    public bool Intersect => Result.Intersect;
}
