using System;
using System.Numerics;
using URWPGSim2D.Collision.Geometry;

using URWPGSim2D.Collision.NarrowPhase;

namespace URWPGSim2D.Collision.Benchmarks.NarrowPhase;

/// <summary>
/// FROZEN BASELINE (benchmarks only): the library's ConvexSat as it was before the vectorised
/// face-separation kernel and the depth-only split (commit fb57fc1), kept so that before and
/// after are measured in the same run. Not used by the library.
/// The separating-axis test with minimum translation vector for two convex polygon-like views,
/// done face by face. For every face i of one shape (outward unit normal nᵢ through vertex vᵢ)
/// the separation sᵢ = min over the other shape's vertices w of nᵢ·(w − vᵢ) is how far the other
/// shape stays outside that face; sᵢ ≥ 0 for some face means the shapes are apart (or only
/// touch). Otherwise the face with the greatest separation over both shapes is the reference
/// face, and −s is the exact penetration depth: the faces of both shapes carry every face of
/// their Minkowski difference, and −sᵢ is that difference's support distance along the face
/// normal, containment included.
/// </summary>
internal static class ConvexSatBaseline
{
    /// <summary>Tolerance (mm) for accepting the fast action point as inside both shapes.</summary>
    private const float InsideTolerance = 1e-3f;

    /// <summary>Separations (mm) closer than this count as a tie between the two shapes' faces.</summary>
    private const float TieTolerance = 1e-4f;

    /// <summary>The MTV moves <paramref name="a"/>; all arithmetic is relative to a's first vertex.</summary>
    public static CollisionDetectionResult Detect(in ConvexView a, in ConvexView b)
    {
        Vector2 origin = a.Vertices[0];
        Span<Vector2> ra = stackalloc Vector2[a.Vertices.Length];
        Span<Vector2> rb = stackalloc Vector2[b.Vertices.Length];
        Relative(a.Vertices, origin, ra);
        Relative(b.Vertices, origin, rb);
        if (!MaxSeparation(ra, a.Normals, rb, out int faceA, out float sepA)
            || !MaxSeparation(rb, b.Normals, ra, out int faceB, out float sepB))
        {
            return CollisionDetectionResult.None;
        }

        // The reference face: the greater separation (the smaller push); ties go to a.
        bool referenceIsA = faceA >= 0 && (faceB < 0 || sepA >= sepB);
        Vector2 normal = referenceIsA ? -a.Normals[faceA] : b.Normals[faceB];
        float depth = referenceIsA ? -sepA : -sepB;

        bool found = referenceIsA
            ? FacePoint(ra, a.Normals, faceA, rb, b.Normals, out Vector2 point, out Vector2 onIncident)
            : FacePoint(rb, b.Normals, faceB, ra, a.Normals, out point, out onIncident);
        if (!found || !InsideBoth(ra, a.Normals, rb, b.Normals, point))
        {
            // Near a corner of the incident shape the half-way point can leave it; the clipped
            // incident points themselves lie on its boundary. Not on a tie between a face of a and
            // a face of b: which one is the reference would then depend on the argument order,
            // and the answer must not. Failing that, the exact centroid.
            bool tie = faceA >= 0 && faceB >= 0 && MathF.Abs(sepA - sepB) <= TieTolerance;
            point = found && !tie && InsideBoth(ra, a.Normals, rb, b.Normals, onIncident)
                ? onIncident
                : ContactRegion.IntersectionCentroid(a, b, origin, normal) - origin;
        }

        return CollisionDetectionResult.FromPlane(normal, depth, origin + point);
    }

    private static void Relative(ReadOnlySpan<Vector2> vertices, Vector2 origin, Span<Vector2> relative)
    {
        for (int i = 0; i < vertices.Length; i++)
        {
            relative[i] = vertices[i] - origin;
        }
    }

    // Greatest separation of `other` from the faces of `reference`; false when some face separates.
    // A single point has no faces: face −1, separation −∞ (the other shape's faces decide).
    private static bool MaxSeparation(ReadOnlySpan<Vector2> reference, ReadOnlySpan<Vector2> normals, ReadOnlySpan<Vector2> other, out int face, out float separation)
    {
        face = -1;
        separation = float.NegativeInfinity;
        for (int i = 0; i < normals.Length; i++)
        {
            Vector2 n = normals[i];
            float lowest = float.PositiveInfinity;
            foreach (Vector2 w in other)
            {
                float d = Vector2.Dot(n, w);
                lowest = d < lowest ? d : lowest;
            }

            float s = lowest - Vector2.Dot(n, reference[i]);
            if (s >= 0f)
            {
                return false;
            }

            if (s > separation)
            {
                separation = s;
                face = i;
            }
        }

        return true;
    }

    /// <summary>
    /// The middle of the overlap between the incident edge (the edge of the other shape most
    /// anti-parallel to the reference face) clipped to the reference face's side planes, and the
    /// reference face: each clipped end point below the face is moved half way toward it
    /// (<paramref name="point"/>); <paramref name="onIncident"/> is the same mean without the move.
    /// False when nothing is below the face (or a shape is flat).
    /// </summary>
    private static bool FacePoint(ReadOnlySpan<Vector2> reference, ReadOnlySpan<Vector2> referenceNormals, int face, ReadOnlySpan<Vector2> incident, ReadOnlySpan<Vector2> incidentNormals, out Vector2 point, out Vector2 onIncident)
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
        int edge = 0;
        float mostAnti = float.PositiveInfinity;
        for (int j = 0; j < incidentNormals.Length; j++)
        {
            float d = Vector2.Dot(incidentNormals[j], n);
            if (d < mostAnti)
            {
                mostAnti = d;
                edge = j;
            }
        }

        Vector2 p1 = incident[edge];
        Vector2 p2 = incident[edge + 1 == incident.Length ? 0 : edge + 1];
        Vector2 t = v2 - v1;
        if (!ClipBelow(ref p1, ref p2, -t, -Vector2.Dot(t, v1)) || !ClipBelow(ref p1, ref p2, t, Vector2.Dot(t, v2)))
        {
            return false;
        }

        float k = Vector2.Dot(n, v1);
        float s1 = Vector2.Dot(n, p1) - k;
        float s2 = Vector2.Dot(n, p2) - k;
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

    // Keeps the part of segment p1p2 with m·p ≤ offset; false when none is left.
    private static bool ClipBelow(ref Vector2 p1, ref Vector2 p2, Vector2 m, float offset)
    {
        float d1 = Vector2.Dot(m, p1) - offset;
        float d2 = Vector2.Dot(m, p2) - offset;
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

    private static bool InsideBoth(ReadOnlySpan<Vector2> ra, ReadOnlySpan<Vector2> na, ReadOnlySpan<Vector2> rb, ReadOnlySpan<Vector2> nb, Vector2 p) =>
        Inside(ra, na, p) && Inside(rb, nb, p);

    // Whether p lies inside a convex view with ≥ 3 vertices, within InsideTolerance.
    private static bool Inside(ReadOnlySpan<Vector2> vertices, ReadOnlySpan<Vector2> normals, Vector2 p)
    {
        if (vertices.Length < 3)
        {
            return false;
        }

        for (int i = 0; i < normals.Length; i++)
        {
            if (Vector2.Dot(normals[i], p - vertices[i]) > InsideTolerance)
            {
                return false;
            }
        }

        return true;
    }
}
