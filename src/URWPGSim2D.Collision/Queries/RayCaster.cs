namespace URWPGSim2D.Collision.Queries;

/// <summary>
/// Where the ray from → to first enters one convex shape: exact clipping of the ray by the
/// shape's edge lines (polygons), a quadratic solved about the closest approach (circles), or a
/// line crossing (segments). A ray that starts inside a shape does not hit it.
/// </summary>
internal static class RayCaster
{
    /// <summary>The first entry of the ray into <paramref name="shape"/>, if any, at <paramref name="fraction"/> ∈ [0, 1] of the way.</summary>
    public static bool Cast(scoped in QueryShape shape, Vector2 from, Vector2 to, out float fraction, out Vector2 normal)
    {
        var v = shape.Vertices;
        if (v.Length >= 3)
        {
            return Polygon(v, shape.Normals, from, to, out fraction, out normal);
        }

        if (v.Length == 2)
        {
            return Segment(v[0], v[1], from, to, out fraction, out normal);
        }

        return Circle(v[0], shape.Radius, from, to, out fraction, out normal);
    }

    /// <summary>
    /// Clips the ray by the half-planes of the edges (Cyrus–Beck): the entry is the last edge the
    /// ray crosses inward. A ray starting on the boundary and pointing in hits at fraction 0.
    /// </summary>
    public static bool Polygon(ReadOnlySpan<Vector2> vertices, ReadOnlySpan<Vector2> normals, Vector2 from, Vector2 to, out float fraction, out Vector2 normal)
    {
        Vector2 d = to - from;
        float lower = 0f, upper = 1f;
        int entry = -1;
        for (int i = 0; i < vertices.Length; i++)
        {
            Vector2 n = normals[i];

            // The ray is inside edge i's half-plane where num − t·den ≥ 0.
            float num = XZPlane.Dot(n, vertices[i] - from);
            float den = XZPlane.Dot(n, d);
            if (den == 0f)
            {
                if (num < 0f)
                {
                    fraction = 0f;
                    normal = default;
                    return false; // parallel, outside
                }
            }
            else if (den < 0f)
            {
                if (num <= lower * den)
                {
                    lower = num / den; // entering later
                    entry = i;
                }
            }
            else if (num < upper * den)
            {
                upper = num / den; // leaving earlier
            }

            if (upper < lower)
            {
                fraction = 0f;
                normal = default;
                return false;
            }
        }

        fraction = lower;
        normal = entry >= 0 ? normals[entry] : default;
        return entry >= 0;
    }

    /// <summary>The crossing of the ray with segment a–b; the normal faces the ray's start.</summary>
    public static bool Segment(Vector2 a, Vector2 b, Vector2 from, Vector2 to, out float fraction, out Vector2 normal)
    {
        fraction = 0f;
        normal = default;
        Vector2 d = to - from;
        Vector2 e = b - a;
        float denominator = XZPlane.Cross(d, e);
        if (denominator == 0f)
        {
            return false; // parallel (a ray along the segment's line grazes it: no entry)
        }

        Vector2 s = a - from;
        float t = XZPlane.Cross(s, e) / denominator;
        float u = XZPlane.Cross(s, d) / denominator;
        if (t < 0f || t > 1f || u < 0f || u > 1f)
        {
            return false;
        }

        Vector2 n = Vector2.Normalize(XZPlane.RightPerp(e));
        fraction = t;
        normal = XZPlane.Dot(n, d) > 0f ? -n : n;
        return true;
    }

    /// <summary>The entry of the ray into the disc, solved about the point of closest approach for precision.</summary>
    public static bool Circle(Vector2 center, float radius, Vector2 from, Vector2 to, out float fraction, out Vector2 normal)
    {
        fraction = 0f;
        normal = default;
        Vector2 d = to - from;
        float length = d.Length();
        Vector2 s = from - center;
        if (length == 0f || !(radius > 0f) || XZPlane.Dot(s, s) < radius * radius)
        {
            return false; // no direction, a point, or a start inside
        }

        Vector2 u = d / length;
        float along = -XZPlane.Dot(s, u);     // distance to the closest approach
        Vector2 across = s + (along * u);      // the centre's offset from the line, reversed
        float h2 = XZPlane.Dot(across, across);
        float r2 = radius * radius;
        if (h2 > r2)
        {
            return false;
        }

        float t = along - MathF.Sqrt(r2 - h2);
        if (t < 0f || t > length)
        {
            return false;
        }

        fraction = t / length;
        Vector2 n = (s + (t * u)) / radius;
        normal = Vector2.Normalize(n);
        return true;
    }
}
