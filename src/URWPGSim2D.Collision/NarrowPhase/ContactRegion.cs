namespace URWPGSim2D.Collision.NarrowPhase;

/// <summary>
/// Where two overlapping shapes touch: the action point of a contact. Every function returns
/// a point of the overlap region (inside both shapes, or on their boundaries), so the point is
/// the same, up to round-off, whichever shape is called first.
/// </summary>
internal static class ContactRegion
{
    /// <summary>
    /// The area centroid of the intersection of two convex views (a flat or single-point view:
    /// the middle of its part inside the other). <paramref name="origin"/> is a nearby point
    /// that all arithmetic is taken relative to. When round-off leaves no region (a grazing
    /// contact) the answer is <see cref="Grazing"/> for the contact <paramref name="normal"/>
    /// (unit, from b toward a).
    /// </summary>
    public static Vector2 IntersectionCentroid(in ConvexView a, in ConvexView b, Vector2 origin, Vector2 normal, bool vector = true)
    {
        if (a.Vertices.Length < 3 || b.Vertices.Length < 3)
        {
            bool found = a.Vertices.Length <= b.Vertices.Length
                ? FlatInside(a, b, origin, out Vector2 point, vector)
                : FlatInside(b, a, origin, out point, vector);
            return found ? point : Grazing(a, b, normal, origin);
        }

        int room = a.Vertices.Length + b.Vertices.Length + 1;
        Span<Vector2> ping = stackalloc Vector2[room];
        Span<Vector2> pong = stackalloc Vector2[room];
        int n = a.Vertices.Length;
        for (int i = 0; i < n; i++)
        {
            ping[i] = a.Vertices[i] - origin;
        }

        var bv = b.Vertices;
        var bn = b.Normals;
        for (int j = 0; j < bv.Length && n > 0; j++)
        {
            n = HalfPlaneClip.Clip(ping[..n], pong, bn[j], Vector2.Dot(bv[j] - origin, bn[j]));
            var swap = ping;
            ping = pong;
            pong = swap;
        }

        return n == 0 ? Grazing(a, b, normal, origin) : origin + Centroid(ping[..n]);
    }

    /// <summary>
    /// The action point of a grazing contact along <paramref name="normal"/> (unit, from b toward
    /// a): on the line midway between a's lowest and b's highest point along the normal, at the
    /// middle (along the tangent) of the overlap of a's part below b's highest line and b's part
    /// above a's lowest line. It lies in the contact region up to the tiny depth of the contact,
    /// whatever the round-off, and does not depend on which shape is called a.
    /// </summary>
    public static Vector2 Grazing(in ConvexView a, in ConvexView b, Vector2 normal, Vector2 origin)
    {
        float lowA = float.PositiveInfinity, highB = float.NegativeInfinity;
        foreach (Vector2 v in a.Vertices)
        {
            lowA = MathF.Min(lowA, Vector2.Dot(v - origin, normal));
        }

        foreach (Vector2 v in b.Vertices)
        {
            highB = MathF.Max(highB, Vector2.Dot(v - origin, normal));
        }

        // The bounding lines never cut a shape's own extreme vertex, so neither part is empty.
        Vector2 tangent = new(-normal.Y, normal.X);
        TangentRange(a, origin, normal, MathF.Max(highB, lowA), tangent, out float a0, out float a1);
        TangentRange(b, origin, -normal, -MathF.Min(lowA, highB), tangent, out float b0, out float b1);
        float t = 0.5f * (MathF.Max(a0, b0) + MathF.Min(a1, b1));
        return origin + tangent * t + normal * (0.5f * (lowA + highB));
    }

    /// <summary>
    /// The interval [lo, hi] of t for which p + t·u lies in the view (empty: lo &gt; hi).
    /// u must be a unit vector. A point or a segment gives the single crossing (or, along
    /// the segment's own line, the segment's extent). A polygon: four faces at a time where the
    /// hardware allows and <paramref name="vector"/> is set, else one at a time.
    /// </summary>
    public static void LineInterval(in ConvexView view, Vector2 p, Vector2 u, out float lo, out float hi, bool vector = true)
    {
        var v = view.Vertices;
        if (v.Length == 1)
        {
            lo = hi = Vector2.Dot(v[0] - p, u);
            return;
        }

        if (v.Length == 2)
        {
            SegmentCrossing(v[0], v[1], p, u, out lo, out hi);
            return;
        }

        if (vector && Vector128.IsHardwareAccelerated)
        {
            FaceLoops.LineInterval(v, view.Normals, p, u, out lo, out hi);
            return;
        }

        PolygonLineInterval(v, view.Normals, p, u, out lo, out hi);
    }

    /// <summary>The interval of a line in a polygon (three or more vertices), one face at a time: the reference for the vector path.</summary>
    internal static void PolygonLineInterval(ReadOnlySpan<Vector2> v, ReadOnlySpan<Vector2> nrm, Vector2 p, Vector2 u, out float lo, out float hi)
    {
        lo = float.NegativeInfinity;
        hi = float.PositiveInfinity;
        for (int i = 0; i < v.Length; i++)
        {
            float s = Vector2.Dot(nrm[i], p - v[i]);
            float d = Vector2.Dot(nrm[i], u);
            if (d > 0f)
            {
                hi = MathF.Min(hi, -s / d);
            }
            else if (d < 0f)
            {
                lo = MathF.Max(lo, -s / d);
            }
            else if (s > 0f)
            {
                lo = float.PositiveInfinity;
                hi = float.NegativeInfinity;
                return;
            }
        }
    }

    /// <summary>The area centroid of a polygon given relative to some origin (vertex mean if it has no area).</summary>
    public static Vector2 Centroid(ReadOnlySpan<Vector2> p)
    {
        Vector2 o = p[0];
        float area2 = 0f;
        Vector2 sum = Vector2.Zero;
        for (int i = 1; i + 1 < p.Length; i++)
        {
            Vector2 e1 = p[i] - o, e2 = p[i + 1] - o;
            float w = XZPlane.Cross(e1, e2);
            area2 += w;
            sum += (e1 + e2) * w;
        }

        float scale = 0f;
        for (int i = 1; i < p.Length; i++)
        {
            scale = MathF.Max(scale, (p[i] - o).LengthSquared());
        }

        if (area2 > 1e-6f * scale)
        {
            return o + sum / (3f * area2);
        }

        Vector2 mean = Vector2.Zero;
        for (int i = 1; i < p.Length; i++)
        {
            mean += p[i] - o;
        }

        return o + mean / p.Length;
    }

    // The middle of the part of a point or segment `flat` that lies inside `other`; false when
    // round-off leaves no such part.
    private static bool FlatInside(in ConvexView flat, in ConvexView other, Vector2 origin, out Vector2 point, bool vector)
    {
        var fv = flat.Vertices;
        if (fv.Length == 1)
        {
            point = fv[0];
            return true;
        }

        if (other.Vertices.Length == 1)
        {
            point = other.Vertices[0];
            return true;
        }

        Vector2 a = fv[0] - origin;
        Vector2 e = fv[1] - fv[0];
        float len = e.Length();
        Vector2 u = e / len;
        LineInterval(other, a + origin, u, out float lo, out float hi, vector);
        lo = MathF.Max(lo, 0f);
        hi = MathF.Min(hi, len);
        point = origin + a + u * (0.5f * (lo + hi));
        return lo <= hi;
    }

    // The extent along `tangent` of the part of `view` (relative to origin) with p·n ≤ offset.
    private static void TangentRange(in ConvexView view, Vector2 origin, Vector2 n, float offset, Vector2 tangent, out float lo, out float hi)
    {
        var v = view.Vertices;
        Span<Vector2> relative = stackalloc Vector2[v.Length];
        Span<Vector2> part = stackalloc Vector2[v.Length + 1];
        for (int i = 0; i < v.Length; i++)
        {
            relative[i] = v[i] - origin;
        }

        int count = HalfPlaneClip.Clip(relative, part, n, offset);
        lo = float.PositiveInfinity;
        hi = float.NegativeInfinity;
        foreach (Vector2 p in part[..count])
        {
            float t = Vector2.Dot(p, tangent);
            lo = MathF.Min(lo, t);
            hi = MathF.Max(hi, t);
        }
    }

    private static void SegmentCrossing(Vector2 a, Vector2 b, Vector2 p, Vector2 u, out float lo, out float hi)
    {
        Vector2 e = b - a;
        float denom = XZPlane.Cross(u, e);
        Vector2 ap = a - p;
        if (MathF.Abs(denom) <= 1e-6f * e.Length())
        {
            float ta = Vector2.Dot(ap, u), tb = Vector2.Dot(b - p, u);
            lo = MathF.Min(ta, tb);
            hi = MathF.Max(ta, tb);
            return;
        }

        float s = XZPlane.Cross(ap, u) / denom;
        if (s < -1e-6f || s > 1f + 1e-6f)
        {
            lo = float.PositiveInfinity;
            hi = float.NegativeInfinity;
            return;
        }

        lo = hi = XZPlane.Cross(ap, e) / denom;
    }
}
