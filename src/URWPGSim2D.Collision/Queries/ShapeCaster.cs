namespace URWPGSim2D.Collision.Queries;

/// <summary>
/// When a shape moved along a translation first touches another, by conservative advancement:
/// at each step the distance d between the shapes and the rate at which the translation closes it
/// along the closest-point normal bound the time still free of contact, and the shape is advanced
/// by exactly that bound. Never past the contact; it stops once the gap is at most the tolerance
/// (<see cref="ShapeQuery.CastTolerance"/>; distances are measured in a frame local to the shapes, so the tolerance holds anywhere in the field).
/// </summary>
internal static class ShapeCaster
{
    /// <summary>Steps before giving up and reporting the contact reached so far (a lower bound of the time).</summary>
    public const int MaxIterations = 50;

    /// <summary>
    /// Casts <paramref name="a"/> along <paramref name="translation"/> against <paramref name="b"/>.
    /// <paramref name="startGap"/> is the gap at fraction 0 (≤ 0: they touch or overlap at the start,
    /// and the caller decides the contact); otherwise the contact is returned at <paramref name="fraction"/>.
    /// </summary>
    public static bool Cast(scoped in QueryShape a, Vector2 translation, scoped in QueryShape b, out float fraction, out Vector2 point, out Vector2 normal, out float startGap)
    {
        float radius = a.Radius + b.Radius;
        float tolerance = ShapeQuery.CastTolerance;
        float t = 0f;
        startGap = 0f;
        for (int iteration = 0; iteration < MaxIterations; iteration++)
        {
            float d = Gjk.Distance(a, t * translation, b, out _, out Vector2 pb, out Vector2 separation);
            float gap = d - radius;
            if (iteration == 0)
            {
                startGap = gap;
                if (gap <= 0f)
                {
                    fraction = 0f;
                    point = pb;
                    normal = d > 0f ? separation / d : default;
                    return true;
                }
            }

            Vector2 n = d > 0f ? separation / d : -SafeNormalize(translation);
            if (gap <= tolerance)
            {
                fraction = t;
                normal = n;
                point = pb + (b.Radius * n);
                return true;
            }

            float closing = -XZPlane.Dot(translation, n);
            if (closing <= 0f)
            {
                break; // moving away along the separating normal: never touches
            }

            t += (gap - (0.5f * tolerance)) / closing;
            if (t > 1f)
            {
                break;
            }

            if (iteration == MaxIterations - 1)
            {
                fraction = t; // not converged: the bound reached, still short of the contact
                normal = n;
                point = pb + (b.Radius * n);
                return true;
            }
        }

        fraction = 0f;
        point = default;
        normal = default;
        return false;
    }

    private static Vector2 SafeNormalize(Vector2 v)
    {
        float length = v.Length();
        return length > 0f ? v / length : Vector2.Zero;
    }
}
