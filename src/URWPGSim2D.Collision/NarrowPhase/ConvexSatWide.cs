using System;
using System.Numerics;
using System.Runtime.CompilerServices;
using System.Runtime.InteropServices;
using System.Runtime.Intrinsics;
using System.Runtime.Intrinsics.X86;
using URWPGSim2D.Collision.Geometry;

namespace URWPGSim2D.Collision.NarrowPhase;

/// <summary>
/// <see cref="ConvexSat"/> for two shapes of three to eight vertices each, each shape in the
/// eight lanes of <see cref="PolygonLanes"/> (256-bit vectors): all of a shape's faces at once
/// against each of the other's vertices; two shapes of at most four vertices share the lanes
/// (a's four faces beside b's, against b's vertices beside a's), so both separations take four
/// steps. Then the reference face, the incident edge, the clipped action point and its inside
/// check, all in registers. Every quantity is computed with the same operations in the same order
/// as in <see cref="ConvexSat"/>'s loops, so the answers are the same bit for bit.
/// </summary>
internal static class ConvexSatWide
{
    /// <summary>Whether the pair can take this path (256-bit vector hardware, three to eight vertices each).</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static bool Fits(in ConvexView a, in ConvexView b) =>
        PolygonLanes.IsSupported && PolygonLanes.Fits(a.Vertices.Length) && PolygonLanes.Fits(b.Vertices.Length);

    /// <summary>As <see cref="ConvexSat.Detect(in ConvexView, in ConvexView)"/> for two polygons with packed lanes (<see cref="PolygonLanes.Pack"/>).</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static CollisionDetectionResult Detect(in ConvexView a, float[] packedA, in ConvexView b, float[] packedB) =>
        Detect(a, ref MemoryMarshal.GetArrayDataReference(packedA), b, ref MemoryMarshal.GetArrayDataReference(packedB));

    /// <summary>As <see cref="ConvexSat.Detect(in ConvexView, in ConvexView)"/>; the views must <see cref="Fits"/>.</summary>
    [MethodImpl(MethodImplOptions.NoInlining)]
    public static CollisionDetectionResult Detect(in ConvexView a, in ConvexView b)
    {
        Span<float> packed = stackalloc float[2 * PolygonLanes.PackedLength];
        ref float pa = ref MemoryMarshal.GetReference(packed);
        ref float pb = ref Unsafe.Add(ref pa, PolygonLanes.PackedLength);
        PolygonLanes.Store(a.Vertices, a.Normals, ref pa);
        PolygonLanes.Store(b.Vertices, b.Normals, ref pb);
        return Detect(a, ref pa, b, ref pb);
    }

    [MethodImpl(MethodImplOptions.NoInlining)]
    private static CollisionDetectionResult Detect(in ConvexView a, ref float pa, in ConvexView b, ref float pb)
    {
        int na = a.Vertices.Length, nb = b.Vertices.Length;
        Vector2 origin = a.Vertices[0];
        var ox = Vector256.Create(origin.X);
        var oz = Vector256.Create(origin.Y);
        var xa = Vector256.LoadUnsafe(ref pa) - ox;
        var za = Vector256.LoadUnsafe(ref pa, 8) - oz;
        var nxa = Vector256.LoadUnsafe(ref pa, 16);
        var nza = Vector256.LoadUnsafe(ref pa, 24);
        var xb = Vector256.LoadUnsafe(ref pb) - ox;
        var zb = Vector256.LoadUnsafe(ref pb, 8) - oz;
        var nxb = Vector256.LoadUnsafe(ref pb, 16);
        var nzb = Vector256.LoadUnsafe(ref pb, 24);

        Vector256<float> sa, sb;
        if (na <= 4 && nb <= 4)
        {
            // a's faces beside b's, against b's vertices beside a's.
            var nx = Vector256.Create(nxa.GetLower(), nxb.GetLower());
            var nz = Vector256.Create(nza.GetLower(), nzb.GetLower());
            var own = (nx * Vector256.Create(xa.GetLower(), xb.GetLower())) + (nz * Vector256.Create(za.GetLower(), zb.GetLower()));
            var wx = Vector256.Create(xb.GetLower(), xa.GetLower());
            var wz = Vector256.Create(zb.GetLower(), za.GetLower());
            var s = Lowest4(nx, nz, wx, wz) - own;
            if (Vector256.GreaterThanOrEqualAny(s, Vector256<float>.Zero))
            {
                return default;
            }

            sa = Avx.Permute2x128(s, s, 0x00);
            sb = Avx.Permute2x128(s, s, 0x11);
        }
        else
        {
            sa = Separation(nxa, nza, xa, za, xb, zb, nb);
            sb = Separation(nxb, nzb, xb, zb, xa, za, na);
            if (Vector256.GreaterThanOrEqualAny(Vector256.MaxNative(sa, sb), Vector256<float>.Zero))
            {
                return default;
            }
        }

        var bestA = PolygonLanes.Greatest(sa);
        var bestB = PolygonLanes.Greatest(sb);
        float sepA = bestA.ToScalar(), sepB = bestB.ToScalar();
        int faceA = PolygonLanes.Index(PolygonLanes.FirstLane(sa, bestA), na);
        int faceB = PolygonLanes.Index(PolygonLanes.FirstLane(sb, bestB), nb);

        // The reference face: the greater separation (the smaller push); ties go to a. The
        // incident edge: the other shape's edge whose normal is most anti-parallel to it.
        bool referenceIsA = sepA >= sepB;
        ConvexView reference = referenceIsA ? a : b;
        ConvexView incident = referenceIsA ? b : a;
        int face = referenceIsA ? faceA : faceB;
        var mx = referenceIsA ? nxb : nxa;
        var mz = referenceIsA ? nzb : nza;
        Vector2 n = Unsafe.Add(ref MemoryMarshal.GetReference(reference.Normals), face);
        var dots = (Vector256.Create(n.X) * mx) + (Vector256.Create(n.Y) * mz);
        int edge = PolygonLanes.Index(PolygonLanes.FirstLane(dots, Least(dots)), incident.Vertices.Length);
        var depth = new ContactDepth(referenceIsA ? -n : n, referenceIsA ? -sepA : -sepB, faceA, sepA, faceB, sepB);

        ref Vector2 rv = ref MemoryMarshal.GetReference(reference.Vertices);
        ref Vector2 iv = ref MemoryMarshal.GetReference(incident.Vertices);
        Vector2 v1 = Unsafe.Add(ref rv, face) - origin;
        Vector2 v2 = Unsafe.Add(ref rv, face + 1 == reference.Vertices.Length ? 0 : face + 1) - origin;
        Vector2 p1 = Unsafe.Add(ref iv, edge) - origin;
        Vector2 p2 = Unsafe.Add(ref iv, edge + 1 == incident.Vertices.Length ? 0 : edge + 1) - origin;
        bool found = ConvexSat.ClipIncident(n, v1, v2, p1, p2, out Vector2 point, out Vector2 onIncident);
        if (!found || !InsideBoth(xa, za, nxa, nza, xb, zb, nxb, nzb, point))
        {
            point = Fallback(a, b, origin, depth, found, onIncident, ref pa, ref pb);
        }

        return ContactResult.Plane(depth.Normal, depth.Depth, origin + point);
    }

    // Near a corner of the incident shape: ConvexSat.Finish's second and third choices.
    [MethodImpl(MethodImplOptions.NoInlining)]
    private static Vector2 Fallback(in ConvexView a, in ConvexView b, Vector2 origin, in ContactDepth depth, bool found, Vector2 onIncident, ref float pa, ref float pb)
    {
        var ox = Vector256.Create(origin.X);
        var oz = Vector256.Create(origin.Y);
        var xa = Vector256.LoadUnsafe(ref pa) - ox;
        var za = Vector256.LoadUnsafe(ref pa, 8) - oz;
        var xb = Vector256.LoadUnsafe(ref pb) - ox;
        var zb = Vector256.LoadUnsafe(ref pb, 8) - oz;
        return found && !ConvexSat.IsTie(depth) && InsideBoth(xa, za, Vector256.LoadUnsafe(ref pa, 16), Vector256.LoadUnsafe(ref pa, 24), xb, zb, Vector256.LoadUnsafe(ref pb, 16), Vector256.LoadUnsafe(ref pb, 24), onIncident)
            ? onIncident
            : ContactRegion.IntersectionCentroid(a, b, origin, depth.Normal) - origin;
    }

    // sᵢ = min over the other shape's vertices w of nᵢ·w − nᵢ·vᵢ for all eight lanes' faces (normal
    // nx, nz through vertex vx, vz), each dot product rounded as Vector2.Dot rounds it.
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    private static Vector256<float> Separation(Vector256<float> nx, Vector256<float> nz, Vector256<float> vx, Vector256<float> vz, Vector256<float> wx, Vector256<float> wz, int otherCount)
    {
        var low = Lowest4(nx, nz, Avx.Permute2x128(wx, wx, 0x00), Avx.Permute2x128(wz, wz, 0x00));
        if (otherCount > 4)
        {
            low = Vector256.MinNative(low, Lowest4(nx, nz, Avx.Permute2x128(wx, wx, 0x11), Avx.Permute2x128(wz, wz, 0x11)));
        }

        return low - ((nx * vx) + (nz * vz));
    }

    // Lane by lane, the least of n·w over the four points of each 128-bit half of wx, wz.
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    private static Vector256<float> Lowest4(Vector256<float> nx, Vector256<float> nz, Vector256<float> wx, Vector256<float> wz)
    {
        var d0 = (nx * Avx.Permute(wx, 0b00_00_00_00)) + (nz * Avx.Permute(wz, 0b00_00_00_00));
        var d1 = (nx * Avx.Permute(wx, 0b01_01_01_01)) + (nz * Avx.Permute(wz, 0b01_01_01_01));
        var d2 = (nx * Avx.Permute(wx, 0b10_10_10_10)) + (nz * Avx.Permute(wz, 0b10_10_10_10));
        var d3 = (nx * Avx.Permute(wx, 0b11_11_11_11)) + (nz * Avx.Permute(wz, 0b11_11_11_11));
        return Vector256.MinNative(Vector256.MinNative(d0, d1), Vector256.MinNative(d2, d3));
    }

    // The least lane, in every lane.
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    private static Vector256<float> Least(Vector256<float> v)
    {
        var low = Vector256.MinNative(v, Avx.Permute2x128(v, v, 0x01));
        low = Vector256.MinNative(low, Avx.Permute(low, 0b01_00_11_10));
        return Vector256.MinNative(low, Avx.Permute(low, 0b10_11_00_01));
    }

    // FaceLoops.Inside for both shapes at once (relative coordinates).
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    private static bool InsideBoth(Vector256<float> xa, Vector256<float> za, Vector256<float> nxa, Vector256<float> nza, Vector256<float> xb, Vector256<float> zb, Vector256<float> nxb, Vector256<float> nzb, Vector2 p)
    {
        var px = Vector256.Create(p.X);
        var pz = Vector256.Create(p.Y);
        var outA = (nxa * (px - xa)) + (nza * (pz - za));
        var outB = (nxb * (px - xb)) + (nzb * (pz - zb));
        return !Vector256.GreaterThanAny(Vector256.MaxNative(outA, outB), Vector256.Create(ConvexSat.InsideTolerance));
    }
}
