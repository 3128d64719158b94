namespace URWPGSim2D.Collision.NarrowPhase;

/// <summary>
/// Circle against any convex polygon-like view by Voronoi regions. The edge of greatest
/// separation s = n·(c − v) is found in one pass (four edges at a time, see
/// <see cref="FaceLoops.Farthest"/>); when s ≤ 0 the centre is inside and the MTV
/// leaves through that edge (depth r − s); otherwise the centre lies in the region of that edge
/// or of one of its two end vertices (decided by two dot products, no angles), which is exact
/// for convex polygons.
/// </summary>
internal static class CircleConvex
{
    /// <summary>The MTV moves the circle; its normal points from the polygon toward the circle.</summary>
    public static CollisionDetectionResult Detect(in Circle circle, in ConvexView polygon) =>
        PolygonLanes.IsSupported && PolygonLanes.Fits(polygon.Vertices.Length) ? CircleLanes.Detect(circle, polygon) : Detect(circle, polygon, vector: true);

    /// <summary>Whether the circle and the polygon overlap and, if so, the normal and depth (no action point).</summary>
    public static bool Depth(in Circle circle, in ConvexView polygon, out ContactDepth depth) => Depth(circle, polygon, out depth, vector: true);

    /// <summary>
    /// <see cref="Detect(in Circle, in ConvexView)"/>, four faces at a time when
    /// <paramref name="vector"/> is set and the hardware has vectors, else one at a time (the
    /// scalar path the vector path must equal).
    /// </summary>
    internal static CollisionDetectionResult Detect(in Circle circle, in ConvexView polygon, bool vector) =>
        Depth(circle, polygon, out ContactDepth depth, vector) ? Complete(circle, polygon, depth) : CollisionDetectionResult.None;

    /// <summary><see cref="Depth(in Circle, in ConvexView, out ContactDepth)"/> (see <see cref="Detect(in Circle, in ConvexView, bool)"/>).</summary>
    internal static bool Depth(in Circle circle, in ConvexView polygon, out ContactDepth depth, bool vector)
    {
        Vector2 c = circle.Center;
        float r = circle.Radius;
        var v = polygon.Vertices;
        var nrm = polygon.Normals;
        Vector2 normal;
        float distance;
        depth = default;
        if (v.Length == 1)
        {
            if (!PointRegion(c, r, v[0], out normal, out distance))
            {
                return false;
            }
        }
        else
        {
            if (!FaceLoops.Farthest(v, nrm, c, r, out int edge, out float maxSep, vector)
                || !Region(c, r, v, nrm, edge, maxSep, out normal, out distance))
            {
                return false;
            }
        }

        depth = new ContactDepth(normal, distance);
        return true;
    }

    /// <summary>
    /// The finished contact for a <paramref name="depth"/> that <see cref="Depth(in Circle, in ConvexView, out ContactDepth)"/>
    /// found for the same circle and polygon: for a polygon the chord's ends by
    /// <see cref="CircleChord"/> (one face at a time, the same bits as <see cref="CircleLanes"/>),
    /// for a segment or a point their crossing of the line.
    /// </summary>
    public static CollisionDetectionResult Complete(in Circle circle, in ConvexView polygon, in ContactDepth depth)
    {
        var v = polygon.Vertices;
        if (v.Length >= 3)
        {
            float r = circle.Radius;
            float lo = CircleChord.FarEnd(v, polygon.Normals, circle.Center, r, depth.Normal);
            return CollisionDetectionResult.FromPlane(depth.Normal, depth.Depth, circle.Center + depth.Normal * CircleChord.Middle(lo, depth.Depth, r));
        }

        ContactRegion.LineInterval(polygon, circle.Center, depth.Normal, out float low, out float high);
        return Finish(circle, depth, low, high);
    }

    /// <summary>
    /// The Voronoi region of the centre <paramref name="c"/> once the edge of greatest separation
    /// (<paramref name="edge"/>, <paramref name="maxSep"/> &lt; r) is known (two vertices or more):
    /// inside, that edge's region or one of its end vertices' (false: the vertex is out of reach).
    /// </summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    internal static bool Region(Vector2 c, float r, ReadOnlySpan<Vector2> v, ReadOnlySpan<Vector2> nrm, int edge, float maxSep, out Vector2 normal, out float distance)
    {
        Vector2 v1 = v[edge];
        Vector2 v2 = v[edge + 1 == v.Length ? 0 : edge + 1];
        if (maxSep <= 0f && v.Length >= 3)
        {
            normal = nrm[edge];
            distance = r - maxSep;
            return true;
        }

        // Only the signs of these dot products matter, so they skip XZPlane.Dot's + 0.
        Vector2 a = c - v1, e = v2 - v1;
        if ((a.X * e.X) + (a.Y * e.Y) <= 0f)
        {
            return PointRegion(c, r, v1, out normal, out distance);
        }

        Vector2 b = c - v2, f = v1 - v2;
        if ((b.X * f.X) + (b.Y * f.Y) <= 0f)
        {
            return PointRegion(c, r, v2, out normal, out distance);
        }

        normal = nrm[edge];
        distance = r - maxSep;
        return true;
    }

    /// <summary>
    /// The result once a segment's or a point's interval [lo, hi] on the line c + t·normal is
    /// known: the middle of its overlap with the circle's [−r, r] (or, when round-off leaves none,
    /// the point at depth − r along the normal).
    /// </summary>
    private static CollisionDetectionResult Finish(in Circle circle, in ContactDepth depth, float lo, float hi)
    {
        float r = circle.Radius;
        lo = ExactMinMax.Max(lo, -r);
        hi = ExactMinMax.Min(hi, r);
        float t = lo <= hi ? 0.5f * (lo + hi) : Math.Clamp(depth.Depth - r, -r, r);
        return CollisionDetectionResult.FromPlane(depth.Normal, depth.Depth, circle.Center + depth.Normal * t);
    }

    // Circle against a single vertex: overlap when |c − p| < r, pushed along (c − p).
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    private static bool PointRegion(Vector2 c, float r, Vector2 p, out Vector2 normal, out float depth)
    {
        Vector2 d = c - p;
        float dist2 = (d.X * d.X) + (d.Y * d.Y); // LengthSquared bit for bit: a sum of squares is never −0

        if (dist2 >= r * r)
        {
            normal = default;
            depth = 0f;
            return false;
        }

        float dist = MathF.Sqrt(dist2);
        normal = dist > 0f ? d / dist : Vector2.UnitX;
        depth = r - dist;
        return true;
    }
}
