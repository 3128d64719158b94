using System.Diagnostics.CodeAnalysis;
using System.Runtime.InteropServices;
using System.Runtime.Intrinsics.Arm;
using System.Runtime.Intrinsics.X86;

namespace URWPGSim2D.Collision.Geometry;

/// <summary>
/// A convex view of three to <see cref="MaxCount"/> vertices held in two groups of four vector
/// lanes, x and z apart: group 0 is vertices (and edge normals) 0–3, group 1 is
/// <see cref="Second"/> to <see cref="Second"/> + 3. A view of five to seven vertices has
/// overlapping groups; one of four has the same group twice; a triangle repeats its last vertex
/// in lane 3. A repeated vertex or face never changes a minimum or a maximum, and ties go to the
/// lowest lane, which is the lowest index, so every answer is the one a loop over the vertices
/// gives. The pair kernels load each shape once and keep it in registers.
/// </summary>
internal struct ConvexLanes
{
    /// <summary>The most vertices a view may have to be held in lanes.</summary>
    public const int MaxCount = 8;

    /// <summary>Vertex x and z, relative to the origin given to <see cref="Load"/>: group 0.</summary>
    public Vector128<float> X0, Z0;

    /// <summary>Vertex x and z, relative to the origin: group 1.</summary>
    public Vector128<float> X1, Z1;

    /// <summary>Edge normal x and z (edge i runs from vertex i to vertex i + 1): group 0.</summary>
    public Vector128<float> NX0, NZ0;

    /// <summary>Edge normal x and z: group 1.</summary>
    public Vector128<float> NX1, NZ1;

    /// <summary>Number of vertices (3 to <see cref="MaxCount"/>).</summary>
    public int Count;

    /// <summary>Index of the vertex in lane 0 of group 1 (Count − 4, or 0 for a triangle).</summary>
    public int Second;

    /// <summary>Whether a view of this many vertices (and as many normals) fits the lanes.</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static bool Fits(int count) => (uint)(count - 3) <= MaxCount - 3;

    /// <summary>Loads a view whose vertex count <see cref="Fits"/>, vertices taken relative to <paramref name="origin"/>.</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static void Load(ReadOnlySpan<Vector2> vertices, ReadOnlySpan<Vector2> normals, Vector2 origin, out ConvexLanes lanes)
    {
        int count = vertices.Length;
        int second = count > 4 ? count - 4 : 0;
        lanes.Count = count;
        lanes.Second = second;
        var o = Vector128.Create(origin.X, origin.Y, origin.X, origin.Y);
        ref float v = ref Unsafe.As<Vector2, float>(ref MemoryMarshal.GetReference(vertices));
        ref float n = ref Unsafe.As<Vector2, float>(ref MemoryMarshal.GetReference(normals));
        Group(ref v, count, 0, out var low, out var high);
        Split(low - o, high - o, out lanes.X0, out lanes.Z0);
        Group(ref n, count, 0, out low, out high);
        Split(low, high, out lanes.NX0, out lanes.NZ0);
        if (count > 4)
        {
            Group(ref v, count, second, out low, out high);
            Split(low - o, high - o, out lanes.X1, out lanes.Z1);
            Group(ref n, count, second, out low, out high);
            Split(low, high, out lanes.NX1, out lanes.NZ1);
        }
        else
        {
            lanes.X1 = lanes.X0;
            lanes.Z1 = lanes.Z0;
            lanes.NX1 = lanes.NX0;
            lanes.NZ1 = lanes.NZ0;
        }
    }

    /// <summary>The vertex or face index of lane <paramref name="lane"/> (0–3: group 0, 4–7: group 1).</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public readonly int Index(int lane) => Math.Min(lane < 4 ? lane : Second + lane - 4, Count - 1);

    /// <summary>A lane (0–7) that holds vertex or face <paramref name="index"/>.</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public readonly int Lane(int index) => index < 4 ? index : index - Second + 4;

    /// <summary>
    /// The lowest lane (0–7) whose value in <paramref name="group0"/> or <paramref name="group1"/>
    /// equals <paramref name="value"/> (broadcast); the value must be in some lane.
    /// </summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static int FirstLane(Vector128<float> group0, Vector128<float> group1, Vector128<float> value) =>
        BitOperations.TrailingZeroCount(Vector128.Equals(group0, value).ExtractMostSignificantBits()
            | (Vector128.Equals(group1, value).ExtractMostSignificantBits() << 4));

    /// <summary>The greatest lane of two groups, in every lane.</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static Vector128<float> Greatest(Vector128<float> group0, Vector128<float> group1)
    {
        var best = Vector128.MaxNative(group0, group1);
        best = Vector128.MaxNative(best, Vector128.Shuffle(best, Vector128.Create(2, 3, 0, 1)));
        return Vector128.MaxNative(best, Vector128.Shuffle(best, Vector128.Create(1, 0, 3, 2)));
    }

    /// <summary>Lane <paramref name="lane"/> of <paramref name="v"/> in all four lanes.</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static Vector128<float> Broadcast(Vector128<float> v, [ConstantExpected(Min = 0, Max = 3)] int lane) =>
        Vector128.Shuffle(v, Vector128.Create(lane));

    // Points at, at+1, at+2, at+3 as two pairs (x, z, x, z); a triangle's last pair repeats point 2.
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    private static void Group(ref float points, int count, int at, out Vector128<float> low, out Vector128<float> high)
    {
        low = Vector128.LoadUnsafe(ref points, (nuint)(2 * at));
        high = count >= 4
            ? Vector128.LoadUnsafe(ref points, (nuint)((2 * at) + 4))
            : Vector128.Create(Unsafe.As<float, long>(ref Unsafe.Add(ref points, 4))).AsSingle();
    }

    // (x0, z0, x1, z1), (x2, z2, x3, z3) → (x0, x1, x2, x3), (z0, z1, z2, z3).
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    private static void Split(Vector128<float> low, Vector128<float> high, out Vector128<float> x, out Vector128<float> z)
    {
        if (Sse.IsSupported)
        {
            x = Sse.Shuffle(low, high, 0b10_00_10_00);
            z = Sse.Shuffle(low, high, 0b11_01_11_01);
        }
        else if (AdvSimd.Arm64.IsSupported)
        {
            x = AdvSimd.Arm64.UnzipEven(low, high);
            z = AdvSimd.Arm64.UnzipOdd(low, high);
        }
        else
        {
            x = Vector128.Create(low.GetElement(0), low.GetElement(2), high.GetElement(0), high.GetElement(2));
            z = Vector128.Create(low.GetElement(1), low.GetElement(3), high.GetElement(1), high.GetElement(3));
        }
    }
}
