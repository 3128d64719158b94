using System.Runtime.InteropServices;

namespace URWPGSim2D.Collision.NarrowPhase;

/// <summary>
/// The separating-axis test with minimum translation vector for two convex polygon-like views,
/// done face by face. For every face i of one shape (outward unit normal nᵢ through vertex vᵢ)
/// the separation sᵢ = min over the other shape's vertices w of nᵢ·(w − vᵢ) is how far the other
/// shape stays outside that face; sᵢ ≥ 0 for some face means the shapes are apart (or only
/// touch). Otherwise the face with the greatest separation over both shapes is the reference
/// face, and −s is the exact penetration depth: the faces of both shapes carry every face of
/// their Minkowski difference, and −sᵢ is that difference's support distance along the face
/// normal, containment included.
/// </summary>
/// <remarks>
/// <see cref="Depth(in ConvexView, in ConvexView, out ContactDepth)"/> is the test without the
/// action point; <see cref="Complete(in ConvexView, in ConvexView, in ContactDepth)"/> adds the
/// action point; <see cref="Detect(in ConvexView, in ConvexView)"/> is both. All arithmetic is
/// relative to a's first vertex. Two shapes of three to eight vertices take
/// <see cref="ConvexSatLanes"/> (both held in vector registers, one pass); the rest take the
/// loops here (see <see cref="FaceLoops"/>), which are also the scalar reference.
/// </remarks>
internal static class ConvexSat
{
    /// <summary>Tolerance (mm) for accepting the fast action point as inside both shapes.</summary>
    internal const float InsideTolerance = 1e-3f;

    /// <summary>Separations (mm) closer than this count as a tie between the two shapes' faces.</summary>
    internal const float TieTolerance = 1e-4f;

    /// <summary>The MTV moves <paramref name="a"/>.</summary>
    public static CollisionDetectionResult Detect(in ConvexView a, in ConvexView b) =>
        ConvexSatWide.Fits(a, b) ? ConvexSatWide.Detect(a, b)
        : ConvexSatLanes.Fits(a, b) ? ConvexSatLanes.Detect(a, b) : Detect(a, b, vector: true);

    /// <summary>Whether the shapes overlap and, if so, the normal and depth of the contact (no action point).</summary>
    public static bool Depth(in ConvexView a, in ConvexView b, out ContactDepth depth) =>
        ConvexSatLanes.Fits(a, b) ? ConvexSatLanes.Depth(a, b, out depth) : Depth(a, b, out depth, vector: true);

    /// <summary>The finished contact for a <paramref name="depth"/> that <see cref="Depth(in ConvexView, in ConvexView, out ContactDepth)"/> found for the same two views.</summary>
    public static CollisionDetectionResult Complete(in ConvexView a, in ConvexView b, in ContactDepth depth) =>
        ConvexSatLanes.Fits(a, b) ? ConvexSatLanes.Complete(a, b, depth) : Complete(a, b, depth, vector: true);

    /// <summary>
    /// <see cref="Detect(in ConvexView, in ConvexView)"/> for views of any size, one loop over the
    /// faces per quantity: four faces at a time when <paramref name="vector"/> is set and the
    /// hardware has vectors, else one at a time (the scalar path every vector path must equal).
    /// </summary>
    internal static CollisionDetectionResult Detect(in ConvexView a, in ConvexView b, bool vector)
    {
        Vector2 origin = a.Vertices[0];
        Span<Vector2> ra = stackalloc Vector2[ConvexPolygon.MaxVertices];
        Span<Vector2> rb = stackalloc Vector2[ConvexPolygon.MaxVertices];
        ra = Relative(a.Vertices, origin, ra);
        rb = Relative(b.Vertices, origin, rb);
        return Separations(ra, a.Normals, rb, b.Normals, out ContactDepth depth, vector)
            ? Finish(a, b, ra, rb, origin, depth, vector)
            : CollisionDetectionResult.None;
    }

    /// <summary><see cref="Depth(in ConvexView, in ConvexView, out ContactDepth)"/> for views of any size (see <see cref="Detect(in ConvexView, in ConvexView, bool)"/>).</summary>
    internal static bool Depth(in ConvexView a, in ConvexView b, out ContactDepth depth, bool vector)
    {
        Vector2 origin = a.Vertices[0];
        Span<Vector2> ra = stackalloc Vector2[ConvexPolygon.MaxVertices];
        Span<Vector2> rb = stackalloc Vector2[ConvexPolygon.MaxVertices];
        ra = Relative(a.Vertices, origin, ra);
        rb = Relative(b.Vertices, origin, rb);
        return Separations(ra, a.Normals, rb, b.Normals, out depth, vector);
    }

    /// <summary><see cref="Complete(in ConvexView, in ConvexView, in ContactDepth)"/> for views of any size (see <see cref="Detect(in ConvexView, in ConvexView, bool)"/>).</summary>
    internal static CollisionDetectionResult Complete(in ConvexView a, in ConvexView b, in ContactDepth depth, bool vector)
    {
        Vector2 origin = a.Vertices[0];
        Span<Vector2> ra = stackalloc Vector2[ConvexPolygon.MaxVertices];
        Span<Vector2> rb = stackalloc Vector2[ConvexPolygon.MaxVertices];
        ra = Relative(a.Vertices, origin, ra);
        rb = Relative(b.Vertices, origin, rb);
        return Finish(a, b, ra, rb, origin, depth, vector);
    }

    // Both shapes' greatest face separations (relative coordinates); false when some face separates.
    private static bool Separations(ReadOnlySpan<Vector2> ra, ReadOnlySpan<Vector2> na, ReadOnlySpan<Vector2> rb, ReadOnlySpan<Vector2> nb, out ContactDepth depth, bool vector)
    {
        if (!FaceLoops.GreatestSeparation(ra, na, rb, out int faceA, out float sepA, vector)
            || !FaceLoops.GreatestSeparation(rb, nb, ra, out int faceB, out float sepB, vector))
        {
            depth = default;
            return false;
        }

        // The reference face: the greater separation (the smaller push); ties go to a.
        bool referenceIsA = faceA >= 0 && (faceB < 0 || sepA >= sepB);
        Vector2 normal = referenceIsA ? -na[faceA] : nb[faceB];
        depth = new ContactDepth(normal, referenceIsA ? -sepA : -sepB, faceA, sepA, faceB, sepB);
        return true;
    }

    // The action point (relative coordinates ra, rb from origin) and the result.
    private static CollisionDetectionResult Finish(in ConvexView a, in ConvexView b, ReadOnlySpan<Vector2> ra, ReadOnlySpan<Vector2> rb, Vector2 origin, in ContactDepth depth, bool vector)
    {
        int faceA = depth.FaceA, faceB = depth.FaceB;
        bool referenceIsA = faceA >= 0 && (faceB < 0 || depth.SeparationA >= depth.SeparationB);
        bool found = referenceIsA
            ? FacePoint(ra, a.Normals, faceA, rb, b.Normals, out Vector2 point, out Vector2 onIncident, vector)
            : FacePoint(rb, b.Normals, faceB, ra, a.Normals, out point, out onIncident, vector);
        if (!found || !InsideBoth(ra, a.Normals, rb, b.Normals, point, vector))
        {
            // Near a corner of the incident shape the half-way point can leave it; the clipped
            // incident points themselves lie on its boundary. Not on a tie between a face of a and
            // a face of b: which one is the reference would then depend on the argument order,
            // and the answer must not. Failing that, the exact centroid.
            bool tie = faceA >= 0 && faceB >= 0 && IsTie(depth);
            point = found && !tie && InsideBoth(ra, a.Normals, rb, b.Normals, onIncident, vector)
                ? onIncident
                : ContactRegion.IntersectionCentroid(a, b, origin, depth.Normal, vector) - origin;
        }

        return CollisionDetectionResult.FromPlane(depth.Normal, depth.Depth, origin + point);
    }

    /// <summary>Whether the two shapes' best faces separate equally (within <see cref="TieTolerance"/>): then the fast action point could depend on the argument order.</summary>
    internal static bool IsTie(in ContactDepth depth) => MathF.Abs(depth.SeparationA - depth.SeparationB) <= TieTolerance;

    // vertices − origin into the buffer (four at a time where the hardware allows); returns the filled part.
    private static Span<Vector2> Relative(ReadOnlySpan<Vector2> vertices, Vector2 origin, Span<Vector2> buffer)
    {
        var relative = buffer[..vertices.Length];
        int i = 0;
        if (Vector256.IsHardwareAccelerated && vertices.Length >= 4)
        {
            ref float src = ref Unsafe.As<Vector2, float>(ref MemoryMarshal.GetReference(vertices));
            ref float dst = ref Unsafe.As<Vector2, float>(ref MemoryMarshal.GetReference(relative));
            var o = Vector256.Create(origin.X, origin.Y, origin.X, origin.Y, origin.X, origin.Y, origin.X, origin.Y);
            for (int at = 0; ; at += 4)
            {
                at = Math.Min(at, vertices.Length - 4);
                (Vector256.LoadUnsafe(ref src, (nuint)(2 * at)) - o).StoreUnsafe(ref dst, (nuint)(2 * at));
                if (at == vertices.Length - 4)
                {
                    return relative;
                }
            }
        }

        for (; i < vertices.Length; i++)
        {
            relative[i] = vertices[i] - origin;
        }

        return relative;
    }

    /// <summary>
    /// The middle of the overlap between the incident edge (the edge of the other shape most
    /// anti-parallel to the reference face) clipped to the reference face's side planes, and the
    /// reference face: each clipped end point below the face is moved half way toward it
    /// (<paramref name="point"/>); <paramref name="onIncident"/> is the same mean without the move.
    /// False when nothing is below the face (or a shape is flat).
    /// </summary>
    private static bool FacePoint(ReadOnlySpan<Vector2> reference, ReadOnlySpan<Vector2> referenceNormals, int face, ReadOnlySpan<Vector2> incident, ReadOnlySpan<Vector2> incidentNormals, out Vector2 point, out Vector2 onIncident, bool vector)
    {
        point = default;
        onIncident = default;
        if (reference.Length < 3 || incident.Length < 3)
        {
            return false;
        }

        Vector2 n = referenceNormals[face];
        Vector2 v1 = reference[face];
        Vector2 v2 = reference[face + 1 == reference.Length ? 0 : face + 1];
        int edge = FaceLoops.LeastDot(incidentNormals, n, vector);

        Vector2 p1 = incident[edge];
        Vector2 p2 = incident[edge + 1 == incident.Length ? 0 : edge + 1];
        return ClipIncident(n, v1, v2, p1, p2, out point, out onIncident);
    }

    /// <summary>
    /// The rest of <see cref="FacePoint"/> once the reference face (normal <paramref name="n"/>, from
    /// <paramref name="v1"/> to <paramref name="v2"/>) and the incident edge <paramref name="p1"/>
    /// <paramref name="p2"/> are known: clip, move half way, average.
    /// </summary>
    internal static bool ClipIncident(Vector2 n, Vector2 v1, Vector2 v2, Vector2 p1, Vector2 p2, out Vector2 point, out Vector2 onIncident)
    {
        point = default;
        onIncident = default;
        Vector2 t = v2 - v1;
        if (!ClipBelow(ref p1, ref p2, -t, -((t.X * v1.X) + (t.Y * v1.Y))) || !ClipBelow(ref p1, ref p2, t, (t.X * v2.X) + (t.Y * v2.Y)))
        {
            return false;
        }

        float k = XZPlane.Dot(n, v1);
        float s1 = XZPlane.Dot(n, p1) - k;
        float s2 = XZPlane.Dot(n, p2) - k;
        Vector2 c1 = p1 - n * (0.5f * s1);
        Vector2 c2 = p2 - n * (0.5f * s2);
        if (s1 <= 0f && s2 <= 0f)
        {
            point = 0.5f * (c1 + c2);
            onIncident = 0.5f * (p1 + p2);
        }
        else if (s1 <= 0f)
        {
            point = c1;
            onIncident = p1;
        }
        else if (s2 <= 0f)
        {
            point = c2;
            onIncident = p2;
        }
        else
        {
            return false;
        }

        return true;
    }

    // Keeps the part of segment p1p2 with m·p ≤ offset; false when none is left. The sign of a
    // zero distance changes nothing here (a point moves only when its distance is > 0, and then
    // d1 − (±0) = d1), so the distances skip XZPlane.Dot's + 0.
    private static bool ClipBelow(ref Vector2 p1, ref Vector2 p2, Vector2 m, float offset)
    {
        float d1 = ((m.X * p1.X) + (m.Y * p1.Y)) - offset;
        float d2 = ((m.X * p2.X) + (m.Y * p2.Y)) - offset;
        if (d1 > 0f && d2 > 0f)
        {
            return false;
        }

        if (d1 > 0f)
        {
            p1 += (p2 - p1) * (d1 / (d1 - d2));
        }
        else if (d2 > 0f)
        {
            p2 += (p1 - p2) * (d2 / (d2 - d1));
        }

        return true;
    }

    private static bool InsideBoth(ReadOnlySpan<Vector2> ra, ReadOnlySpan<Vector2> na, ReadOnlySpan<Vector2> rb, ReadOnlySpan<Vector2> nb, Vector2 p, bool vector) =>
        ra.Length >= 3 && rb.Length >= 3 && FaceLoops.Inside(ra, na, p, InsideTolerance, vector) && FaceLoops.Inside(rb, nb, p, InsideTolerance, vector);
}
