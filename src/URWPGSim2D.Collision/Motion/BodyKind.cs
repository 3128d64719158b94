namespace URWPGSim2D.Collision.Motion;

/// <summary>What a motion world body is: one of the three moving kinds or a static one.</summary>
public enum BodyKind : byte
{
    /// <summary>A moving circle (a ball): translates only.</summary>
    Circle,

    /// <summary>A moving convex polygon, given about its own origin: translates and turns about that origin.</summary>
    Polygon,

    /// <summary>A moving fish: translates and turns about its body centre; its joints keep their angles within a step unless set to turn over it (<see cref="MotionWorld.SetJointTargets"/>).</summary>
    Fish,

    /// <summary>A static shape (circle, box, 8-DOP, polygon or segment) that never moves.</summary>
    Static,

    /// <summary>The pool's four walls: everything must stay inside the field's bounds.</summary>
    Walls,
}
