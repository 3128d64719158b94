using System.Runtime.InteropServices;
using System.Runtime.Intrinsics.X86;

namespace URWPGSim2D.Collision.NarrowPhase;

/// <summary>
/// <see cref="CircleConvex"/> for a polygon of three to eight vertices held in the eight lanes
/// of <see cref="PolygonLanes"/> (256-bit vectors). One pass gives every face's separation
/// s = n·(c − v); the face of greatest s is picked (the lowest lane on a tie), and only then is
/// its region decided: when s ≤ 0 the centre is inside and, when the centre lies over the face
/// (neither end vertex's test holds), the contact is the face's own normal and r − s, read
/// straight out of the lanes; only a centre beyond an end vertex takes the square root and the
/// division, for all lanes at once, and keeps the picked lane's. So the common contacts wait for
/// neither. The action point's chord is <see cref="CircleChord"/>'s: its near end from the
/// depth, its far end −r unless the circle's deepest point lies outside a face (one comparison
/// over the lanes), else the greatest −s/d over the lanes. The result is written from vectors
/// already laid out as the world's x, 0, z (<see cref="ContactResult.World"/>). Every quantity is
/// computed with the same operations in the same order as in <see cref="CircleConvex"/>,
/// <see cref="FaceLoops"/> and <see cref="CircleChord"/>, so the answers are the same bit for bit.
/// </summary>
internal static class CircleLanes
{
    /// <summary>As <see cref="CircleConvex.Detect(in Circle, in ConvexView)"/> for a polygon packed by <see cref="PolygonLanes.Pack"/>.</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static CollisionDetectionResult Detect(in Circle circle, float[] packed) =>
        Detect(circle, ref MemoryMarshal.GetArrayDataReference(packed));

    /// <summary>As <see cref="CircleConvex.Detect(in Circle, in ConvexView)"/> for a view whose vertex count <see cref="PolygonLanes.Fits"/>.</summary>
    [MethodImpl(MethodImplOptions.NoInlining)]
    public static CollisionDetectionResult Detect(in Circle circle, in ConvexView polygon)
    {
        Span<float> packed = stackalloc float[PolygonLanes.PackedLength];
        ref float p = ref MemoryMarshal.GetReference(packed);
        PolygonLanes.Store(polygon.Vertices, polygon.Normals, ref p);
        return Detect(circle, ref p);
    }

    // The test on a packed polygon (PolygonLanes).
    [MethodImpl(MethodImplOptions.NoInlining)]
    private static CollisionDetectionResult Detect(in Circle circle, ref float packed)
    {
        // The centre and the radius broadcast straight from the circle's floats (no shuffles).
        ref float circleFloats = ref Circle.Floats(circle);
        var x = Vector256.LoadUnsafe(ref packed);
        var z = Vector256.LoadUnsafe(ref packed, 8);
        var nx = Vector256.LoadUnsafe(ref packed, 16);
        var nz = Vector256.LoadUnsafe(ref packed, 24);
        var cx = Vector256.Create(circleFloats);
        var cz = Vector256.Create(Unsafe.Add(ref circleFloats, 1));
        var radius = Vector256.Create(Unsafe.Add(ref circleFloats, 2));
        var dx = cx - x;
        var dz = cz - z;
        var s = (nx * dx) + (nz * dz);
        if (Vector256.GreaterThanOrEqual(s, radius).ExtractMostSignificantBits() != 0)
        {
            return default;
        }

        float r = Unsafe.Add(ref circleFloats, 2);
        var best = PolygonLanes.Greatest(s);
        int lane = PolygonLanes.FirstLane(s, best);
        Vector256<float> normalX, normalZ;
        float depth;
        if (best.ToScalar() > 0f && BeyondAnEnd(cx, cz, lane, ref packed, x, z, dx, dz, out var atStart, out var bx, out var bz))
        {
            // The region of the vertex v nearer the centre: the normal (c − v)/|c − v| (+x when c
            // is on v) and the depth r − |c − v|, for all lanes at once, the picked one kept.
            var zero = Vector256<float>.Zero;
            var dist2 = Vector256.ConditionalSelect(atStart, (dx * dx) + (dz * dz), (bx * bx) + (bz * bz));
            if (((Vector256.GreaterThanOrEqual(dist2, Vector256.Create(r * r)).ExtractMostSignificantBits() >> lane) & 1) != 0)
            {
                return default;
            }

            var dist = Vector256.Sqrt(dist2);
            var positive = Vector256.GreaterThan(dist, zero);
            var pick = Vector256.Create(lane);
            normalX = Avx2.PermuteVar8x32(Vector256.ConditionalSelect(positive, Vector256.ConditionalSelect(atStart, dx, bx) / dist, Vector256<float>.One), pick);
            normalZ = Avx2.PermuteVar8x32(Vector256.ConditionalSelect(positive, Vector256.ConditionalSelect(atStart, dz, bz) / dist, zero), pick);
            depth = r - Avx2.PermuteVar8x32(dist, pick).ToScalar();
        }
        else
        {
            // Inside, or over the face: its normal (straight from the lanes, in every lane) and r − s.
            normalX = Vector256.Create(Unsafe.Add(ref packed, 16 + lane));
            normalZ = Vector256.Create(Unsafe.Add(ref packed, 24 + lane));
            depth = r - best.ToScalar();
        }

        // The action point (CircleChord): the far end of the chord is −r unless the circle's
        // deepest point lies outside some face.
        var dn = (nx * normalX) + (nz * normalZ);
        float lo = Vector256.GreaterThan(s, radius * dn).ExtractMostSignificantBits() != 0 ? FarEnd(s, dn, r) : -r;
        var normal = Sse41.Insert(normalX.GetLower(), normalZ.GetLower(), 0b00_10_1010); // x 0 z 0
        var centre = Sse.UnpackLow(Vector128.CreateScalarUnsafe(Unsafe.As<float, double>(ref circleFloats)).AsSingle(), Vector128<float>.Zero); // x 0 z 0
        return ContactResult.World(normal, depth, centre + (normal * CircleChord.Middle(lo, depth, r)));
    }

    // Whether the centre (outside the picked face's line) lies beyond one of the face's ends:
    // its start vertex v1 (this lane) and end vertex v2 (the next vertex's lane) decide
    // ((c − v1)·(v2 − v1) ≤ 0: v1's region, atStart; else (c − v2)·(v1 − v2) ≤ 0: v2's; else
    // the face's). The second test is taken as (c − v2)·(v2 − v1) ≥ 0: the same sum negated,
    // exactly (products and sums round symmetrically), so one edge vector serves both. b is c − v2.
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    private static bool BeyondAnEnd(
        Vector256<float> cx, Vector256<float> cz, int lane, ref float packed, Vector256<float> x, Vector256<float> z, Vector256<float> dx, Vector256<float> dz,
        out Vector256<float> atStart, out Vector256<float> bx, out Vector256<float> bz)
    {
        var x2 = Vector256.LoadUnsafe(ref packed, 32);
        var z2 = Vector256.LoadUnsafe(ref packed, 40);
        bx = cx - x2;
        bz = cz - z2;
        var ex = x2 - x;
        var ez = z2 - z;
        atStart = Vector256.LessThanOrEqual((dx * ex) + (dz * ez), Vector256<float>.Zero);
        var atEnd = Vector256.GreaterThanOrEqual((bx * ex) + (bz * ez), Vector256<float>.Zero);
        return (((atStart | atEnd).ExtractMostSignificantBits() >> lane) & 1) != 0;
    }

    // CircleChord.FarEnd's slow part: the greatest −s/d over the faces with d < 0, and −r.
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    private static float FarEnd(Vector256<float> s, Vector256<float> dn, float r)
    {
        var low = Vector256.ConditionalSelect(Vector256.LessThan(dn, Vector256<float>.Zero), -s / dn, Vector256.Create(-r));
        return CircleChord.Unsigned(PolygonLanes.Greatest(low).ToScalar());
    }
}
