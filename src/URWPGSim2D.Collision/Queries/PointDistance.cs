namespace URWPGSim2D.Collision.Queries;

/// <summary>
/// The distance from a point to the core of a query shape in closed form (no iteration): to the
/// vertex of a circle, to the nearest point of a segment, and for an outline of three vertices or
/// more 0 inside it (on the inner side of every edge) and otherwise the distance to its nearest edge.
/// </summary>
internal static class PointDistance
{
    /// <summary>The distance from <paramref name="point"/> to the core of <paramref name="shape"/> (0 inside), with the core's nearest point.</summary>
    public static float ToCore(scoped in QueryShape shape, Vector2 point, out Vector2 nearest)
    {
        var v = shape.Vertices;
        if (v.Length == 1)
        {
            nearest = v[0];
            return Vector2.Distance(point, v[0]);
        }

        if (v.Length == 2)
        {
            return ToSegment(v[0], v[1], point, out nearest);
        }

        // Counter-clockwise: inside is on the left of every edge. Outside, the nearest point lies on
        // an edge the point is outside of; those are compared by squared distance, one root at the end.
        bool inside = true;
        float best = float.PositiveInfinity;
        nearest = v[0];
        for (int i = 0; i < v.Length; i++)
        {
            Vector2 a = v[i], e = v[i == v.Length - 1 ? 0 : i + 1] - a, w = point - a;
            if (XZPlane.Cross(e, w) >= 0f)
            {
                continue;
            }

            inside = false;
            float length2 = XZPlane.Dot(e, e);
            float t = Math.Clamp(XZPlane.Dot(w, e) / length2, 0f, 1f);
            Vector2 at = t >= 1f ? a + e : a + (t * e);
            float d2 = Vector2.DistanceSquared(point, at);
            if (d2 < best)
            {
                best = d2;
                nearest = at;
            }
        }

        if (inside)
        {
            nearest = point;
            return 0f;
        }

        return MathF.Sqrt(best);
    }

    /// <summary>The distance from <paramref name="point"/> to the segment <paramref name="a"/>–<paramref name="b"/>, with the segment's nearest point.</summary>
    public static float ToSegment(Vector2 a, Vector2 b, Vector2 point, out Vector2 nearest)
    {
        Vector2 e = b - a, w = point - a;
        float length2 = XZPlane.Dot(e, e);
        float t = length2 > 0f ? Math.Clamp(XZPlane.Dot(w, e) / length2, 0f, 1f) : 0f;
        nearest = t >= 1f ? b : a + (t * e);
        return Vector2.Distance(point, nearest);
    }
}
