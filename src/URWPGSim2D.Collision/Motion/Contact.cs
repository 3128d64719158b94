namespace URWPGSim2D.Collision.Motion;

/// <summary>One contact the <see cref="MotionWorld"/> reports: two bodies overlapping at a time of the step.</summary>
public readonly struct Contact
{
    internal Contact(Body bodyA, Body bodyB, in Hit hit, double time, bool pressing = false)
    {
        Pressing = pressing;
        BodyA = bodyA.Handle;
        BodyB = bodyB.Handle;
        Intersect = hit.Intersect;
        PartA = hit.PartA < 0 ? null : (FishPart)hit.PartA;
        PartB = hit.PartB < 0 ? null : (FishPart)hit.PartB;
        Time = time;
        if (hit.Intersect)
        {
            Mtv = hit.Mtv;
            Normal = hit.Normal;
            Point = hit.Point;
            Depth = Mtv.Length(); // the length of this contact's own translation (a contact carried into another frame keeps its depth only to the last bit)
        }
    }

    /// <summary>The first body (always a moving one): <see cref="Result"/>'s translation moves it out of <see cref="BodyB"/>.</summary>
    public BodyId BodyA { get; }

    /// <summary>The second body: moving, static or the walls.</summary>
    public BodyId BodyB { get; }

    /// <summary>The overlap: minimum translation of A, unit normal from B toward A, action point (X–Z plane, mm).</summary>
    public CollisionDetectionResult Result =>
        CollisionDetectionResult.InPlane(Intersect, Mtv, Normal, Point);

    /// <summary>The leaf of A in contact when A is a fish, else null.</summary>
    public FishPart? PartA { get; }

    /// <summary>The leaf of B in contact when B is a fish, else null.</summary>
    public FishPart? PartB { get; }

    /// <summary>
    /// Whether this is a pressing contact: the pair was already touching (answered at one of its
    /// last two samples, see <see cref="MotionWorld.PressingContacts"/>) and is answered where a
    /// sample found it, not at a time of first contact, so <see cref="Depth"/> is how far the
    /// bodies moved into each other since then. The wedge policy does not count the correction of
    /// a pressing contact (<see cref="WedgePolicy.CorrectionsBeforeRejecting"/>).
    /// </summary>
    public bool Pressing { get; }

    /// <summary>When in the step, as a fraction 0 … 1 of its duration (the time of first contact, or of the sample that found a pressing contact).</summary>
    public double Time { get; }

    /// <summary>Whether the bodies overlap (false for "no contact").</summary>
    public bool Intersect { get; }

    /// <summary>The minimum translation of A in the plane (X, Y = world X, Z), mm; zero when the bodies do not overlap.</summary>
    public Vector2 Mtv { get; }

    /// <summary>The unit normal from B toward A in the plane; zero when the bodies do not overlap.</summary>
    public Vector2 Normal { get; }

    /// <summary>The action point in the plane, mm; zero when the bodies do not overlap.</summary>
    public Vector2 Point { get; }

    /// <summary>How deep the bodies overlap (the length of <see cref="Mtv"/>), mm; 0 when they do not.</summary>
    public float Depth { get; }
}
