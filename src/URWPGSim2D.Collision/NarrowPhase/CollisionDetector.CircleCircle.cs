namespace URWPGSim2D.Collision;

/// <content>Circle against circle, directly from the centre distance.</content>
public static partial class CollisionDetector
{
    /// <summary>
    /// Circle <paramref name="a"/> against circle <paramref name="b"/>: they overlap when the centre
    /// distance d = |cₐ − c_b| is below rₐ + r_b; the MTV is (rₐ + r_b − d) along (cₐ − c_b)/d
    /// (+X for concentric circles), and the action point is the middle of the overlap of the
    /// two diameters on the centre line.
    /// </summary>
    /// <param name="a">The shape the MTV moves.</param>
    /// <param name="b">The other shape.</param>
    /// <returns>The contact, or <see cref="CollisionDetectionResult.None"/>.</returns>
    public static CollisionDetectionResult Detect(in Circle a, in Circle b)
    {
        Vector2 d = a.Center - b.Center;
        float reach = a.Radius + b.Radius;
        float dist2 = d.LengthSquared();
        if (dist2 >= reach * reach)
        {
            return CollisionDetectionResult.None;
        }

        float dist = MathF.Sqrt(dist2);
        Vector2 n = dist > 0f ? d / dist : Vector2.UnitX;

        // On the line b.Center + t·n: b covers [−r_b, r_b], a covers [dist − rₐ, dist + rₐ].
        float lo = MathF.Max(-b.Radius, dist - a.Radius);
        float hi = MathF.Min(b.Radius, dist + a.Radius);
        return CollisionDetectionResult.FromPlane(n, reach - dist, b.Center + n * (0.5f * (lo + hi)));
    }
}
