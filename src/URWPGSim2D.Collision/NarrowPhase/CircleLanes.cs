using System;
using System.Numerics;
using System.Runtime.CompilerServices;
using System.Runtime.InteropServices;
using System.Runtime.Intrinsics;
using System.Runtime.Intrinsics.X86;
using URWPGSim2D.Collision.Geometry;
using URWPGSim2D.Collision.Shapes;

namespace URWPGSim2D.Collision.NarrowPhase;

/// <summary>
/// <see cref="CircleConvex"/> for a polygon of three to eight vertices held in the eight lanes
/// of <see cref="PolygonLanes"/> (256-bit vectors): one pass gives every face's separation
/// s = n·(c − v) and, beside the search for the greatest, every lane's Voronoi region, normal and
/// depth as if its face were the farthest (both end vertices' tests, the square root and the
/// division done for all lanes at once, off the search's path), so that only a lane is left to
/// pick. The action point's chord is <see cref="CircleChord"/>'s: its near end from the depth, its
/// far end −r unless the circle's deepest point lies outside a face (one comparison over the
/// lanes), else the greatest −s/d over the lanes. Every quantity is computed with the same operations in
/// the same order as in <see cref="CircleConvex"/>, <see cref="FaceLoops"/> and
/// <see cref="CircleChord"/>, so the answers are the same bit for bit.
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
        Vector2 c = circle.Center;
        float r = circle.Radius;
        var x = Vector256.LoadUnsafe(ref packed);
        var z = Vector256.LoadUnsafe(ref packed, 8);
        var nx = Vector256.LoadUnsafe(ref packed, 16);
        var nz = Vector256.LoadUnsafe(ref packed, 24);
        var cx = Vector256.Create(c.X);
        var cz = Vector256.Create(c.Y);
        var radius = Vector256.Create(r);
        var dx = cx - x;
        var dz = cz - z;
        var s = (nx * dx) + (nz * dz);
        if (Vector256.GreaterThanOrEqualAny(s, radius))
        {
            return default;
        }

        var best = PolygonLanes.Greatest(s);
        int lane = PolygonLanes.FirstLane(s, best);

        // Beside the search for the farthest face, every lane's answer as if its face were the
        // one: the edge's start v1 (this lane) and end v2 (the next vertex's lane) decide the
        // region ((c − v1)·(v2 − v1) ≤ 0: v1's; else (c − v2)·(v1 − v2) ≤ 0: v2's; else the
        // edge's, or inside when s ≤ 0), then the normal and depth of that region. The second
        // test is taken as (c − v2)·(v2 − v1) ≥ 0: the same sum negated, exactly (products and
        // sums round symmetrically), so the same answer with one edge vector.
        var zero = Vector256<float>.Zero;
        var x2 = Vector256.LoadUnsafe(ref packed, 32);
        var z2 = Vector256.LoadUnsafe(ref packed, 40);
        var bx = cx - x2;
        var bz = cz - z2;
        var ex = x2 - x;
        var ez = z2 - z;
        var atStart = Vector256.LessThanOrEqual((dx * ex) + (dz * ez), zero);
        var atEnd = Vector256.GreaterThanOrEqual((bx * ex) + (bz * ez), zero);
        var dist2 = Vector256.ConditionalSelect(atStart, (dx * dx) + (dz * dz), (bx * bx) + (bz * bz));
        var px = Vector256.ConditionalSelect(atStart, dx, bx);
        var pz = Vector256.ConditionalSelect(atStart, dz, bz);
        var dist = Vector256.Sqrt(dist2);
        var positive = Vector256.GreaterThan(dist, zero);
        var vertex = (atStart | atEnd) & Vector256.GreaterThan(s, zero);
        var normalX = Vector256.ConditionalSelect(vertex, Vector256.ConditionalSelect(positive, px / dist, Vector256<float>.One), nx);
        var normalZ = Vector256.ConditionalSelect(vertex, Vector256.ConditionalSelect(positive, pz / dist, zero), nz);
        var depth = radius - Vector256.ConditionalSelect(vertex, dist, s);
        uint outOfReach = (vertex & Vector256.GreaterThanOrEqual(dist2, Vector256.Create(r * r))).ExtractMostSignificantBits();
        if (((outOfReach >> lane) & 1) != 0)
        {
            return default;
        }

        // The picked lane's normal in every lane, its depth, and the action point (CircleChord):
        // the far end of the chord is −r unless the circle's deepest point lies outside some face.
        var pick = Vector256.Create(lane);
        var normalXs = Avx2.PermuteVar8x32(normalX, pick);
        var normalZs = Avx2.PermuteVar8x32(normalZ, pick);
        Vector2 normal = new(normalXs.ToScalar(), normalZs.ToScalar());
        float contactDepth = Avx2.PermuteVar8x32(depth, pick).ToScalar();
        var dn = (nx * normalXs) + (nz * normalZs);
        float lo = Vector256.GreaterThanAny(s, radius * dn) ? FarEnd(s, dn, r) : -r;
        return ContactResult.Plane(normal, contactDepth, c + normal * CircleChord.Middle(lo, contactDepth, r));
    }

    // CircleChord.FarEnd's slow part: the greatest −s/d over the faces with d < 0, and −r.
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    private static float FarEnd(Vector256<float> s, Vector256<float> dn, float r)
    {
        var low = Vector256.ConditionalSelect(Vector256.LessThan(dn, Vector256<float>.Zero), -s / dn, Vector256.Create(-r));
        return CircleChord.Unsigned(PolygonLanes.Greatest(low).ToScalar());
    }
}
