namespace URWPGSim2D.Collision.Motion;

/// <summary>
/// The time of first contact of two bodies moving rigidly over an interval: the
/// <see cref="MotionWorld"/>'s own detection, run on a world of these two bodies for one step of the
/// interval's length. The pair is sampled on its own clock, often enough that it cannot pass
/// through itself between two samples and not at all while its bounding circles are too far apart
/// to meet; the first overlapping sample is refined (a false-position guess, then bisection) until
/// nothing moves more than <see cref="MotionTolerances.TimeOfImpactTolerance"/> inside the
/// bracket. A fish's joints keep their angles throughout; the bodies given are not changed.
/// </summary>
public static class TimeOfImpact
{
    /// <summary>The first time in [0, <paramref name="seconds"/>] at which the two bodies overlap, with the contact then.</summary>
    /// <param name="a">The first body (its MTV is reported).</param>
    /// <param name="b">The second body.</param>
    /// <param name="seconds">Length of the interval, s (positive and finite).</param>
    /// <returns>The contact at its time of first contact, or <see cref="TimeOfImpactResult.NoContact"/>.</returns>
    /// <exception cref="ArgumentException">Both bodies are static (or walls), a body is default, or <paramref name="seconds"/> is not positive and finite.</exception>
    public static TimeOfImpactResult Find(in MovingBody a, in MovingBody b, float seconds)
    {
        if (!(seconds > 0f) || float.IsPositiveInfinity(seconds))
        {
            throw new ArgumentException($"interval must be positive and finite, got {seconds}", nameof(seconds));
        }

        Check(a, nameof(a));
        Check(b, nameof(b));
        if (!IsMoving(a.Kind) && !IsMoving(b.Kind))
        {
            throw new ArgumentException("at least one body must move (both are static)", nameof(b));
        }

        var world = new MotionWorld();
        BodyId first = Add(world, a);
        BodyId second = Add(world, b);

        // Overlapping at the start: the contact is at time 0 (the motion world's first sample would find it later).
        bool aMoves = IsMoving(a.Kind);
        Contact now = aMoves ? world.Detect(first, second) : world.Detect(second, first);
        if (now.Depth > MotionTolerances.ContactSlop)
        {
            return new TimeOfImpactResult(0f, now, swap: !aMoves);
        }

        var recorder = new FirstContact();
        world.Step(seconds, recorder);
        return recorder.Found
            ? new TimeOfImpactResult((float)(recorder.Contact.Time * seconds), recorder.Contact, swap: recorder.Contact.BodyA != first)
            : TimeOfImpactResult.NoContact;
    }

    private static bool IsMoving(BodyKind kind) => kind is BodyKind.Circle or BodyKind.Polygon or BodyKind.Fish;

    private static void Check(in MovingBody m, string name)
    {
        bool valid = m.Kind switch
        {
            BodyKind.Circle => m.CircleShape.Radius > 0f,
            BodyKind.Polygon => m.Outline.Vertices.Length > 0,
            BodyKind.Fish => m.Model is not null,
            BodyKind.Static => true,
            _ => m.Field is not null,
        };
        if (!valid)
        {
            throw new ArgumentException(m.Kind == BodyKind.Polygon ? "polygon is default(ConvexPolygon)" : "body is default(MovingBody)", name);
        }
    }

    // The body in the two-body world, with its motion over the interval.
    private static BodyId Add(MotionWorld world, in MovingBody m)
    {
        BodyId id = m.Kind switch
        {
            BodyKind.Circle => world.AddCircle(m.CircleShape.Radius, m.CircleShape.Center),
            BodyKind.Polygon => world.AddPolygon(m.Outline, m.Position, m.Heading),
            BodyKind.Fish => world.AddFish(m.Model!.Size, m.Model.Pose),
            BodyKind.Static => world.AddStatic(m.StaticShape),
            _ => world.AddWalls(m.Field!),
        };
        if (IsMoving(m.Kind))
        {
            world.SetVelocity(id, m.Velocity, m.AngularVelocity);
        }

        return id;
    }

    // Keeps the step's first contact and takes the bodies out of contact handling: nothing after it matters.
    private sealed class FirstContact : IContactHandler
    {
        public bool Found { get; private set; }

        public Contact Contact { get; private set; }

        public void OnContact(MotionWorld motionWorld, in Contact contact)
        {
            if (!Found)
            {
                Found = true;
                Contact = contact;
            }

            motionWorld.SetCollides(contact.BodyA, false);
            if (IsMoving(motionWorld.KindOf(contact.BodyB)))
            {
                motionWorld.SetCollides(contact.BodyB, false);
            }
        }

        public void OnMoveRejected(MotionWorld motionWorld, BodyId body)
        {
        }
    }
}
