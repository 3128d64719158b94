using System.Runtime.InteropServices;

namespace URWPGSim2D.Collision.NarrowPhase;

/// <summary>
/// <see cref="ConvexSat"/> for two views of three to eight vertices, each loaded once into
/// <see cref="ConvexLanes"/> and kept in vector registers through the whole test: both shapes'
/// face separations, the reference face, the incident edge and the inside check of the action
/// point. Every quantity is computed with the same operations in the same order as in
/// <see cref="ConvexSat"/>'s loops, so the answers are the same bit for bit.
/// </summary>
internal static class ConvexSatLanes
{
    /// <summary>Whether the pair can take this path (hardware vectors, three to eight vertices each).</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static bool Fits(in ConvexView a, in ConvexView b) =>
        Vector128.IsHardwareAccelerated && ConvexLanes.Fits(a.Vertices.Length) && ConvexLanes.Fits(b.Vertices.Length);

    /// <summary>As <see cref="ConvexSat.Detect(in ConvexView, in ConvexView)"/>; the views must <see cref="Fits"/>.</summary>
    [MethodImpl(MethodImplOptions.NoInlining)]
    public static CollisionDetectionResult Detect(in ConvexView a, in ConvexView b)
    {
        Vector2 origin = a.Vertices[0];
        ConvexLanes.Load(a.Vertices, a.Normals, origin, out var la);
        ConvexLanes.Load(b.Vertices, b.Normals, origin, out var lb);
        return Separations(a.Normals, b.Normals, la, lb, out ContactDepth depth, out int laneA, out int laneB)
            ? Finish(a, b, la, lb, origin, depth, laneA, laneB)
            : CollisionDetectionResult.None;
    }

    /// <summary>As <see cref="ConvexSat.Depth(in ConvexView, in ConvexView, out ContactDepth)"/>; the views must <see cref="Fits"/>.</summary>
    [MethodImpl(MethodImplOptions.NoInlining)]
    public static bool Depth(in ConvexView a, in ConvexView b, out ContactDepth depth)
    {
        Vector2 origin = a.Vertices[0];
        ConvexLanes.Load(a.Vertices, a.Normals, origin, out var la);
        ConvexLanes.Load(b.Vertices, b.Normals, origin, out var lb);
        return Separations(a.Normals, b.Normals, la, lb, out depth, out _, out _);
    }

    /// <summary>As <see cref="ConvexSat.Complete(in ConvexView, in ConvexView, in ContactDepth)"/>; the views must <see cref="Fits"/>.</summary>
    [MethodImpl(MethodImplOptions.NoInlining)]
    public static CollisionDetectionResult Complete(in ConvexView a, in ConvexView b, in ContactDepth depth)
    {
        Vector2 origin = a.Vertices[0];
        ConvexLanes.Load(a.Vertices, a.Normals, origin, out var la);
        ConvexLanes.Load(b.Vertices, b.Normals, origin, out var lb);
        return Finish(a, b, la, lb, origin, depth, la.Lane(depth.FaceA), lb.Lane(depth.FaceB));
    }

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    private static bool Separations(ReadOnlySpan<Vector2> an, ReadOnlySpan<Vector2> bn, in ConvexLanes la, in ConvexLanes lb, out ContactDepth depth, out int laneA, out int laneB)
    {
        var sa0 = Separation(la.NX0, la.NZ0, la.X0, la.Z0, lb);
        var sa1 = la.Count > 4 ? Separation(la.NX1, la.NZ1, la.X1, la.Z1, lb) : sa0;
        var bestA = ConvexLanes.Greatest(sa0, sa1);
        var sb0 = Separation(lb.NX0, lb.NZ0, lb.X0, lb.Z0, la);
        var sb1 = lb.Count > 4 ? Separation(lb.NX1, lb.NZ1, lb.X1, lb.Z1, la) : sb0;
        var bestB = ConvexLanes.Greatest(sb0, sb1);
        if (Vector128.GreaterThanOrEqualAny(bestA, Vector128<float>.Zero) || Vector128.GreaterThanOrEqualAny(bestB, Vector128<float>.Zero))
        {
            depth = default;
            laneA = laneB = 0;
            return false;
        }

        float sepA = bestA.ToScalar(), sepB = bestB.ToScalar();
        laneA = ConvexLanes.FirstLane(sa0, sa1, bestA);
        laneB = ConvexLanes.FirstLane(sb0, sb1, bestB);
        int faceA = la.Index(laneA);
        int faceB = lb.Index(laneB);
        bool referenceIsA = sepA >= sepB;
        Vector2 normal = referenceIsA ? -Unsafe.Add(ref MemoryMarshal.GetReference(an), faceA) : Unsafe.Add(ref MemoryMarshal.GetReference(bn), faceB);
        depth = new ContactDepth(normal, referenceIsA ? -sepA : -sepB, faceA, sepA, faceB, sepB);
        return true;
    }

    // sᵢ = min over the other shape's vertices w of nᵢ·w − nᵢ·vᵢ for four faces (normal nx, nz
    // through vertex vx, vz), each dot product rounded as Vector2.Dot rounds it.
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    private static Vector128<float> Separation(Vector128<float> nx, Vector128<float> nz, Vector128<float> vx, Vector128<float> vz, in ConvexLanes other)
    {
        var low = Lowest(nx, nz, other.X0, other.Z0);
        if (other.Count > 4)
        {
            low = Vector128.MinNative(low, Lowest(nx, nz, other.X1, other.Z1));
        }

        return low - ((nx * vx) + (nz * vz));
    }

    // The least of n·w over the four points of one group, lane by lane.
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    private static Vector128<float> Lowest(Vector128<float> nx, Vector128<float> nz, Vector128<float> x, Vector128<float> z)
    {
        var d0 = (nx * ConvexLanes.Broadcast(x, 0)) + (nz * ConvexLanes.Broadcast(z, 0));
        var d1 = (nx * ConvexLanes.Broadcast(x, 1)) + (nz * ConvexLanes.Broadcast(z, 1));
        var d2 = (nx * ConvexLanes.Broadcast(x, 2)) + (nz * ConvexLanes.Broadcast(z, 2));
        var d3 = (nx * ConvexLanes.Broadcast(x, 3)) + (nz * ConvexLanes.Broadcast(z, 3));
        return Vector128.MinNative(Vector128.MinNative(d0, d1), Vector128.MinNative(d2, d3));
    }

    // The action point and the result, as ConvexSat.Finish computes them (laneA, laneB: the lanes
    // of the two shapes' best faces).
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    private static CollisionDetectionResult Finish(in ConvexView a, in ConvexView b, in ConvexLanes la, in ConvexLanes lb, Vector2 origin, in ContactDepth depth, int laneA, int laneB)
    {
        bool referenceIsA = depth.SeparationA >= depth.SeparationB;
        bool found = referenceIsA
            ? FacePoint(a.Vertices, a.Normals, depth.FaceA, b.Vertices, lb.Count, IncidentEdge(la, laneA, lb), origin, out Vector2 point, out Vector2 onIncident)
            : FacePoint(b.Vertices, b.Normals, depth.FaceB, a.Vertices, la.Count, IncidentEdge(lb, laneB, la), origin, out point, out onIncident);
        if (!found || !InsideBoth(la, lb, point))
        {
            point = Fallback(a, b, la, lb, origin, depth, found, onIncident);
        }

        return CollisionDetectionResult.FromPlane(depth.Normal, depth.Depth, origin + point);
    }

    // Near a corner of the incident shape: ConvexSat.Finish's second and third choices.
    [MethodImpl(MethodImplOptions.NoInlining)]
    private static Vector2 Fallback(in ConvexView a, in ConvexView b, in ConvexLanes la, in ConvexLanes lb, Vector2 origin, in ContactDepth depth, bool found, Vector2 onIncident)
    {
        return found && !ConvexSat.IsTie(depth) && InsideBoth(la, lb, onIncident)
            ? onIncident
            : ContactRegion.IntersectionCentroid(a, b, origin, depth.Normal) - origin;
    }

    // The incident edge for the reference face in lane `lane` of `reference`: found for all four
    // faces of the lane's group at once, which keeps the search beside the face selection rather
    // than after it.
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    private static int IncidentEdge(in ConvexLanes reference, int lane, in ConvexLanes incident)
    {
        var first = Vector128.Create(lane < 4 ? -1 : 0).AsSingle();
        var edges = IncidentEdges(Vector128.ConditionalSelect(first, reference.NX0, reference.NX1), Vector128.ConditionalSelect(first, reference.NZ0, reference.NZ1), incident);
        return edges.GetElement(lane & 3);
    }

    // For four reference faces at once (normals nx, nz), the incident edge of each (lowest index
    // on a tie): the least n·m over the other shape's edge normals m, scanned in index order.
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    private static Vector128<int> IncidentEdges(Vector128<float> nx, Vector128<float> nz, in ConvexLanes other)
    {
        Least(nx, nz, other.NX0, other.NZ0, Vector128.Create(0, 1, 2, Math.Min(3, other.Count - 1)), out var least, out var edges);
        if (other.Count > 4)
        {
            Least(nx, nz, other.NX1, other.NZ1, Vector128.Create(other.Second) + Vector128.Create(0, 1, 2, 3), out var least1, out var edges1);
            Earlier(ref least, ref edges, least1, edges1);
        }

        return edges;
    }

    // The least of n·m over four normals m (x, z) of one group, and the index of the first that gives it.
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    private static void Least(Vector128<float> nx, Vector128<float> nz, Vector128<float> mx, Vector128<float> mz, Vector128<int> indices, out Vector128<float> least, out Vector128<int> edges)
    {
        var d0 = (nx * ConvexLanes.Broadcast(mx, 0)) + (nz * ConvexLanes.Broadcast(mz, 0));
        var d1 = (nx * ConvexLanes.Broadcast(mx, 1)) + (nz * ConvexLanes.Broadcast(mz, 1));
        var d2 = (nx * ConvexLanes.Broadcast(mx, 2)) + (nz * ConvexLanes.Broadcast(mz, 2));
        var d3 = (nx * ConvexLanes.Broadcast(mx, 3)) + (nz * ConvexLanes.Broadcast(mz, 3));
        var i0 = Vector128.Shuffle(indices, Vector128.Create(0));
        var i1 = Vector128.Shuffle(indices, Vector128.Create(1));
        var i2 = Vector128.Shuffle(indices, Vector128.Create(2));
        var i3 = Vector128.Shuffle(indices, Vector128.Create(3));
        Earlier(ref d0, ref i0, d1, i1);
        Earlier(ref d2, ref i2, d3, i3);
        Earlier(ref d0, ref i0, d2, i2);
        least = d0;
        edges = i0;
    }

    // Keeps the later candidate only where it is strictly less (ties go to the earlier index).
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    private static void Earlier(ref Vector128<float> least, ref Vector128<int> edges, Vector128<float> later, Vector128<int> laterEdges)
    {
        var less = Vector128.LessThan(later, least);
        least = Vector128.ConditionalSelect(less, later, least);
        edges = Vector128.ConditionalSelect(less.AsInt32(), laterEdges, edges);
    }

    // ConvexSat.FacePoint once the incident edge is known (both indices valid).
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    private static bool FacePoint(ReadOnlySpan<Vector2> referenceVertices, ReadOnlySpan<Vector2> referenceNormals, int face, ReadOnlySpan<Vector2> incidentVertices, int incidentCount, int edge, Vector2 origin, out Vector2 point, out Vector2 onIncident)
    {
        ref Vector2 rv = ref MemoryMarshal.GetReference(referenceVertices);
        Vector2 n = Unsafe.Add(ref MemoryMarshal.GetReference(referenceNormals), face);
        Vector2 v1 = Unsafe.Add(ref rv, face) - origin;
        Vector2 v2 = Unsafe.Add(ref rv, face + 1 == referenceVertices.Length ? 0 : face + 1) - origin;
        ref Vector2 iv = ref MemoryMarshal.GetReference(incidentVertices);
        Vector2 p1 = Unsafe.Add(ref iv, edge) - origin;
        Vector2 p2 = Unsafe.Add(ref iv, edge + 1 == incidentCount ? 0 : edge + 1) - origin;
        return ConvexSat.ClipIncident(n, v1, v2, p1, p2, out point, out onIncident);
    }

    // FaceLoops.Inside for both shapes at once.
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    private static bool InsideBoth(in ConvexLanes la, in ConvexLanes lb, Vector2 p)
    {
        var px = Vector128.Create(p.X);
        var pz = Vector128.Create(p.Y);
        var outA = Outside(la.NX0, la.NZ0, la.X0, la.Z0, px, pz);
        if (la.Count > 4)
        {
            outA = Vector128.MaxNative(outA, Outside(la.NX1, la.NZ1, la.X1, la.Z1, px, pz));
        }

        var outB = Outside(lb.NX0, lb.NZ0, lb.X0, lb.Z0, px, pz);
        if (lb.Count > 4)
        {
            outB = Vector128.MaxNative(outB, Outside(lb.NX1, lb.NZ1, lb.X1, lb.Z1, px, pz));
        }

        return !Vector128.GreaterThanAny(Vector128.MaxNative(outA, outB), Vector128.Create(ConvexSat.InsideTolerance));
    }

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    private static Vector128<float> Outside(Vector128<float> nx, Vector128<float> nz, Vector128<float> vx, Vector128<float> vz, Vector128<float> px, Vector128<float> pz) =>
        (nx * (px - vx)) + (nz * (pz - vz));
}
