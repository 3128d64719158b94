using System.Runtime.InteropServices;
using System.Runtime.Intrinsics.X86;

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

    /// <summary>As <see cref="ConvexSat.Detect(in ConvexView, in ConvexView)"/> for two polygons of at most eight vertices (both have packed lanes).</summary>
    [MethodImpl(MethodImplOptions.NoInlining)]
    public static CollisionDetectionResult Detect(in ConvexPolygon a, in ConvexPolygon b)
    {
        var pair = new PolygonPair(a, b);
        return Detect(ref MemoryMarshal.GetArrayDataReference(a.Lanes!), ref MemoryMarshal.GetArrayDataReference(b.Lanes!), pair);
    }

    /// <summary>As <see cref="ConvexSat.Detect(in ConvexView, in ConvexView)"/>; the views must <see cref="Fits"/>.</summary>
    [MethodImpl(MethodImplOptions.NoInlining)]
    public static CollisionDetectionResult Detect(in ConvexView a, in ConvexView b)
    {
        Span<float> packed = stackalloc float[2 * PolygonLanes.PackedLength];
        ref float pa = ref MemoryMarshal.GetReference(packed);
        ref float pb = ref Unsafe.Add(ref pa, PolygonLanes.PackedLength);
        PolygonLanes.Store(a.Vertices, a.Normals, ref pa);
        PolygonLanes.Store(b.Vertices, b.Normals, ref pb);
        var pair = new ViewPair(a, b);
        return Detect(ref pa, ref pb, pair);
    }

    // The test on two packed shapes; `shapes` gives the intersection centroid when the fast action point fails.
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    private static CollisionDetectionResult Detect<TShapes>(ref float pa, ref float pb, scoped in TShapes shapes)
        where TShapes : IShapePair, allows ref struct
    {
        int na = PolygonLanes.Count(ref pa), nb = PolygonLanes.Count(ref pb);
        var ox = Vector256.Create(pa);
        var oz = Vector256.Create(Unsafe.Add(ref pa, 8));
        var xa = Vector256.LoadUnsafe(ref pa) - ox;
        var za = Vector256.LoadUnsafe(ref pa, 8) - oz;
        var nxa = Vector256.LoadUnsafe(ref pa, 16);
        var nza = Vector256.LoadUnsafe(ref pa, 24);
        var xb = Vector256.LoadUnsafe(ref pb) - ox;
        var zb = Vector256.LoadUnsafe(ref pb, 8) - oz;
        var nxb = Vector256.LoadUnsafe(ref pb, 16);
        var nzb = Vector256.LoadUnsafe(ref pb, 24);

        Vector256<float> sa, sb;
        Vector256<int> incidentEdges = default;
        bool small = na <= 4 && nb <= 4;
        if (small)
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

            // Beside the choice of the reference face, the incident edge of every face that could
            // be it: for a's faces the lane of b's most anti-parallel edge normal, for b's a's.
            incidentEdges = IncidentEdges4(nx, nz, Vector256.Create(nxb.GetLower(), nxa.GetLower()), Vector256.Create(nzb.GetLower(), nza.GetLower()));
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
        int laneA = PolygonLanes.FirstLane(sa, bestA);
        int laneB = PolygonLanes.FirstLane(sb, bestB);

        // The reference face: the greater separation (the smaller push); ties go to a. The
        // incident edge: the other shape's edge whose normal is most anti-parallel to it.
        bool referenceIsA = sepA >= sepB;
        int lane = referenceIsA ? laneA : laneB;
        var pick = Vector256.CreateScalarUnsafe(lane);
        var n = Vector2.Create(Avx2.PermuteVar8x32(referenceIsA ? nxa : nxb, pick).ToScalar(), Avx2.PermuteVar8x32(referenceIsA ? nza : nzb, pick).ToScalar());
        var mx = referenceIsA ? nxb : nxa;
        var mz = referenceIsA ? nzb : nza;
        Vector256<int> edge;
        if (small)
        {
            edge = Avx2.PermuteVar8x32(incidentEdges, Vector256.CreateScalarUnsafe(referenceIsA ? laneA : laneB + 4));
        }
        else
        {
            var dots = (Vector256.Create(n.X) * mx) + (Vector256.Create(n.Y) * mz);
            edge = Vector256.CreateScalarUnsafe(PolygonLanes.FirstLane(dots, PolygonLanes.Least(dots)));
        }
        var depth = new ContactDepth(referenceIsA ? -n : n, referenceIsA ? -sepA : -sepB, PolygonLanes.Index(laneA, na), sepA, PolygonLanes.Index(laneB, nb), sepB);

        // The reference face from v1 to v2, the incident edge from p1 to p2 (relative coordinates).
        ref float reference = ref referenceIsA ? ref pa : ref pb;
        ref float incident = ref referenceIsA ? ref pb : ref pa;
        Vector2 v1 = Vector2.Create(Avx2.PermuteVar8x32(referenceIsA ? xa : xb, pick).ToScalar(), Avx2.PermuteVar8x32(referenceIsA ? za : zb, pick).ToScalar());
        Vector2 v2 = Vector2.Create(Avx2.PermuteVar8x32(Vector256.LoadUnsafe(ref reference, 32), pick).ToScalar() - ox.ToScalar(), Avx2.PermuteVar8x32(Vector256.LoadUnsafe(ref reference, 40), pick).ToScalar() - oz.ToScalar());
        Vector2 p1 = Vector2.Create(Avx2.PermuteVar8x32(referenceIsA ? xb : xa, edge).ToScalar(), Avx2.PermuteVar8x32(referenceIsA ? zb : za, edge).ToScalar());
        Vector2 p2 = Vector2.Create(Avx2.PermuteVar8x32(Vector256.LoadUnsafe(ref incident, 32), edge).ToScalar() - ox.ToScalar(), Avx2.PermuteVar8x32(Vector256.LoadUnsafe(ref incident, 40), edge).ToScalar() - oz.ToScalar());
        bool found = ConvexSat.ClipIncident(n, v1, v2, p1, p2, out Vector2 point, out Vector2 onIncident);
        if (!found || !InsideBoth(xa, za, nxa, nza, xb, zb, nxb, nzb, point))
        {
            point = Fallback(ref pa, ref pb, shapes, depth, found, onIncident);
        }

        Vector2 origin = Vector2.Create(ox.ToScalar(), oz.ToScalar());
        return ContactResult.Plane(depth.Normal, depth.Depth, origin + point);
    }

    // Near a corner of the incident shape: ConvexSat.Finish's second and third choices.
    [MethodImpl(MethodImplOptions.NoInlining)]
    private static Vector2 Fallback<TShapes>(ref float pa, ref float pb, scoped in TShapes shapes, in ContactDepth depth, bool found, Vector2 onIncident)
        where TShapes : IShapePair, allows ref struct
    {
        var ox = Vector256.Create(pa);
        var oz = Vector256.Create(Unsafe.Add(ref pa, 8));
        var xa = Vector256.LoadUnsafe(ref pa) - ox;
        var za = Vector256.LoadUnsafe(ref pa, 8) - oz;
        var xb = Vector256.LoadUnsafe(ref pb) - ox;
        var zb = Vector256.LoadUnsafe(ref pb, 8) - oz;
        Vector2 origin = Vector2.Create(ox.ToScalar(), oz.ToScalar());
        return found && !ConvexSat.IsTie(depth) && InsideBoth(xa, za, Vector256.LoadUnsafe(ref pa, 16), Vector256.LoadUnsafe(ref pa, 24), xb, zb, Vector256.LoadUnsafe(ref pb, 16), Vector256.LoadUnsafe(ref pb, 24), onIncident)
            ? onIncident
            : shapes.IntersectionCentroid(origin, depth.Normal) - origin;
    }

    // The two shapes of a test, for the rare intersection centroid.
    private interface IShapePair
    {
        Vector2 IntersectionCentroid(Vector2 origin, Vector2 normal);
    }

    private readonly ref struct ViewPair : IShapePair
    {
        private readonly ConvexView _a, _b;

        public ViewPair(in ConvexView a, in ConvexView b)
        {
            _a = a;
            _b = b;
        }

        public Vector2 IntersectionCentroid(Vector2 origin, Vector2 normal) => ContactRegion.IntersectionCentroid(_a, _b, origin, normal);
    }

    private readonly ref struct PolygonPair : IShapePair
    {
        private readonly ref readonly ConvexPolygon _a, _b;

        public PolygonPair(in ConvexPolygon a, in ConvexPolygon b)
        {
            _a = ref a;
            _b = ref b;
        }

        public Vector2 IntersectionCentroid(Vector2 origin, Vector2 normal) => ContactRegion.IntersectionCentroid(_a.View(), _b.View(), origin, normal);
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

    // For the eight faces (normals nx, nz) of two shapes of at most four vertices side by side,
    // the lane (0–3) of the other shape's edge whose normal m gives the least n·m (the first on a
    // tie), m taken from each 128-bit half of mx, mz in lane order.
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    private static Vector256<int> IncidentEdges4(Vector256<float> nx, Vector256<float> nz, Vector256<float> mx, Vector256<float> mz)
    {
        var least = (nx * Avx.Permute(mx, 0b00_00_00_00)) + (nz * Avx.Permute(mz, 0b00_00_00_00));
        var edges = Vector256<int>.Zero;
        Earlier(ref least, ref edges, (nx * Avx.Permute(mx, 0b01_01_01_01)) + (nz * Avx.Permute(mz, 0b01_01_01_01)), 1);
        Earlier(ref least, ref edges, (nx * Avx.Permute(mx, 0b10_10_10_10)) + (nz * Avx.Permute(mz, 0b10_10_10_10)), 2);
        Earlier(ref least, ref edges, (nx * Avx.Permute(mx, 0b11_11_11_11)) + (nz * Avx.Permute(mz, 0b11_11_11_11)), 3);
        return edges;
    }

    // Takes the later candidate only where it is strictly less (ties go to the earlier edge).
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    private static void Earlier(ref Vector256<float> least, ref Vector256<int> edges, Vector256<float> later, int edge)
    {
        var less = Vector256.LessThan(later, least);
        least = Vector256.ConditionalSelect(less, later, least);
        edges = Vector256.ConditionalSelect(less.AsInt32(), Vector256.Create(edge), edges);
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
