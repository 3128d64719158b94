namespace URWPGSim2D.Collision.NarrowPhase;

/// <summary>
/// The action point of a circle against a convex polygon (three vertices or more): the middle of
/// the overlap of the circle's [−r, r] with the polygon's chord [lo, hi] on the line c + t·normal.
/// Neither end of the chord needs every face's crossing:
/// <list type="bullet">
/// <item>hi, where the line leaves the polygon toward the circle's centre, is the contact feature
/// itself: the line meets the face of greatest separation s at t = −s (edge region, or centre
/// inside) or passes through the vertex at distance d from the centre at t = −d (vertex region),
/// and the depth is r − s or r − d, so hi = depth − r;</item>
/// <item>lo, where the line enters the polygon on its far side, matters only when it is above −r,
/// which is exactly when the circle's deepest point c − r·normal (its point farthest into the
/// polygon) lies outside the polygon: outside some face, s &gt; r·d with d = n·normal. Only then
/// is lo taken as the greatest −s/d over the faces with d &lt; 0; otherwise it is −r, and the
/// test is all it costs.</item>
/// </list>
/// The vector path (<see cref="CircleLanes"/>) computes s, d, the test and the greatest −s/d with
/// the same operations, so both paths give the same bits.
/// </summary>
internal static class CircleChord
{
    /// <summary>
    /// The chord's far end lo (at least −r) for the circle (centre <paramref name="c"/>, radius
    /// <paramref name="r"/>) along <paramref name="normal"/>, face by face.
    /// </summary>
    public static float FarEnd(ReadOnlySpan<Vector2> vertices, ReadOnlySpan<Vector2> normals, Vector2 c, float r, Vector2 normal)
    {
        bool outside = false;
        for (int i = 0; i < vertices.Length; i++)
        {
            outside |= Separation(vertices[i], normals[i], c) > r * Along(normals[i], normal);
        }

        if (!outside)
        {
            return -r;
        }

        float lo = -r;
        for (int i = 0; i < vertices.Length; i++)
        {
            float d = Along(normals[i], normal);
            if (d < 0f)
            {
                lo = ExactMinMax.Max(lo, -Separation(vertices[i], normals[i], c) / d);
            }
        }

        return Unsigned(lo);
    }

    /// <summary>The action point's t on the line c + t·normal once the far end <paramref name="lo"/> (≥ −r) is known.</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static float Middle(float lo, float depth, float r)
    {
        float exit = depth - r;
        float hi = exit < r ? exit : r; // r > 0: no signed zero to choose between
        return lo <= hi ? 0.5f * (lo + hi) : Math.Clamp(exit, -r, r);
    }

    /// <summary>
    /// A greatest −s/d with its zero's sign made positive, so the order of a reduction cannot
    /// show: adding +0 keeps every other value and turns −0 into +0, without a branch.
    /// </summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static float Unsigned(float lo) => lo + 0f;

    // s = n·(c − v) with the lanes' operations: the two products, then their sum.
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    private static float Separation(Vector2 v, Vector2 n, Vector2 c) => (n.X * (c.X - v.X)) + (n.Y * (c.Y - v.Y));

    // d = n·normal with the lanes' operations.
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    private static float Along(Vector2 n, Vector2 normal) => (n.X * normal.X) + (n.Y * normal.Y);
}
