using System.Runtime.InteropServices;
using System.Runtime.Intrinsics.X86;

namespace URWPGSim2D.Collision.Geometry;

/// <summary>
/// A convex shape of three to eight vertices in the eight lanes of 256-bit vectors, x and z
/// apart (structure of arrays): lanes 0–3 hold vertices (and edge normals) 0–3, lanes 4–7 hold
/// <c>second</c> to <c>second</c> + 3, where <c>second</c> is <c>count</c> − 4 (five to eight
/// vertices), or 0 (three or four: the upper half repeats the lower). A triangle repeats vertex 2
/// in lane 3. This is the layout of <see cref="ConvexLanes"/> with its two groups side by side,
/// so a repeated vertex or face never changes a minimum or a maximum and the lowest lane holding
/// a value is its lowest index. <see cref="Shapes.ConvexPolygon"/> packs its lanes once, when
/// built (<see cref="Pack"/>); a view is loaded on every test (<see cref="Load(ReadOnlySpan{Vector2}, ReadOnlySpan{Vector2}, out Vector256{float}, out Vector256{float}, out Vector256{float}, out Vector256{float})"/>).
/// </summary>
internal static class PolygonLanes
{
    /// <summary>
    /// Floats in a packed shape: vertex x, z, normal x, normal z, and x, z of the next vertex (the
    /// end of the lane's edge), eight lanes each, then the vertex count (an integer's bits).
    /// </summary>
    public const int PackedLength = 49;

    /// <summary>Where a packed shape keeps its vertex count (an integer's bits).</summary>
    public const int CountSlot = 48;

    // For each count 3–8, the lane holding the vertex after each lane's vertex (the edge's end).
    private static readonly int[] NextTable = BuildNextTable();

    /// <summary>Whether the kernels on these lanes run on this machine (256-bit vector hardware).</summary>
    public static bool IsSupported
    {
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        get => Avx2.IsSupported;
    }

    /// <summary>Whether a shape of this many vertices fits the lanes.</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static bool Fits(int count) => (uint)(count - 3) <= 5;

    /// <summary>The vertex or face index held by <paramref name="lane"/> (0–7) for a shape of <paramref name="count"/> vertices.</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static int Index(int lane, int count) => Math.Min(lane < 4 ? lane : (count > 4 ? count - 4 : 0) + lane - 4, count - 1);

    /// <summary>A lane holding vertex or face <paramref name="index"/>.</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static int Lane(int index, int count) => index < 4 ? index : index - (count - 4) + 4;

    /// <summary>The lanes of a shape whose vertex count <see cref="Fits"/>, packed once (world coordinates).</summary>
    public static float[] Pack(ReadOnlySpan<Vector2> vertices, ReadOnlySpan<Vector2> normals)
    {
        int count = vertices.Length;
        var packed = new float[PackedLength];
        for (int lane = 0; lane < 8; lane++)
        {
            int i = Index(lane, count);
            packed[lane] = vertices[i].X;
            packed[8 + lane] = vertices[i].Y;
            packed[16 + lane] = normals[i].X;
            packed[24 + lane] = normals[i].Y;
            int next = i + 1 == count ? 0 : i + 1;
            packed[32 + lane] = vertices[next].X;
            packed[40 + lane] = vertices[next].Y;
        }

        packed[CountSlot] = BitConverter.Int32BitsToSingle(count);
        return packed;
    }

    /// <summary>Loads packed lanes (see <see cref="Pack"/>).</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static void Load(float[] packed, out Vector256<float> x, out Vector256<float> z, out Vector256<float> nx, out Vector256<float> nz)
    {
        ref float p = ref MemoryMarshal.GetArrayDataReference(packed);
        x = Vector256.LoadUnsafe(ref p);
        z = Vector256.LoadUnsafe(ref p, 8);
        nx = Vector256.LoadUnsafe(ref p, 16);
        nz = Vector256.LoadUnsafe(ref p, 24);
    }

    /// <summary>The vertex count of a packed shape.</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static int Count(ref float packed) => Unsafe.As<float, int>(ref Unsafe.Add(ref packed, CountSlot));

    /// <summary>Packs the lanes of a view whose vertex count <see cref="Fits"/> into <paramref name="packed"/> (<see cref="PackedLength"/> floats), as <see cref="Pack"/> does.</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static void Store(ReadOnlySpan<Vector2> vertices, ReadOnlySpan<Vector2> normals, ref float packed)
    {
        Load(vertices, normals, out var x, out var z, out var nx, out var nz);
        var next = Next(vertices.Length);
        x.StoreUnsafe(ref packed);
        z.StoreUnsafe(ref packed, 8);
        nx.StoreUnsafe(ref packed, 16);
        nz.StoreUnsafe(ref packed, 24);
        Avx2.PermuteVar8x32(x, next).StoreUnsafe(ref packed, 32);
        Avx2.PermuteVar8x32(z, next).StoreUnsafe(ref packed, 40);
        Unsafe.As<float, int>(ref Unsafe.Add(ref packed, CountSlot)) = vertices.Length;
    }

    /// <summary>Loads the lanes of a view whose vertex count <see cref="Fits"/> (vertices and normals interleaved x, z).</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static void Load(ReadOnlySpan<Vector2> vertices, ReadOnlySpan<Vector2> normals, out Vector256<float> x, out Vector256<float> z, out Vector256<float> nx, out Vector256<float> nz)
    {
        int count = vertices.Length;
        Split(ref Unsafe.As<Vector2, float>(ref MemoryMarshal.GetReference(vertices)), count, out x, out z);
        Split(ref Unsafe.As<Vector2, float>(ref MemoryMarshal.GetReference(normals)), count, out nx, out nz);
    }

    /// <summary>For a shape of <paramref name="count"/> vertices, the lane of the vertex after each lane's vertex (for a permutation).</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static Vector256<int> Next(int count) =>
        Vector256.LoadUnsafe(ref MemoryMarshal.GetArrayDataReference(NextTable), (nuint)(8 * (count - 3)));

    /// <summary>The greatest lane, in every lane.</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static Vector256<float> Greatest(Vector256<float> v)
    {
        var best = Vector256.MaxNative(v, Avx.Permute2x128(v, v, 0x01));
        best = Vector256.MaxNative(best, Avx.Permute(best, 0b01_00_11_10));
        return Vector256.MaxNative(best, Avx.Permute(best, 0b10_11_00_01));
    }

    /// <summary>The least lane, in every lane.</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static Vector256<float> Least(Vector256<float> v)
    {
        var low = Vector256.MinNative(v, Avx.Permute2x128(v, v, 0x01));
        low = Vector256.MinNative(low, Avx.Permute(low, 0b01_00_11_10));
        return Vector256.MinNative(low, Avx.Permute(low, 0b10_11_00_01));
    }

    /// <summary>The lowest lane where <paramref name="v"/> equals <paramref name="value"/> (which must be in some lane).</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static int FirstLane(Vector256<float> v, Vector256<float> value) =>
        BitOperations.TrailingZeroCount(Vector256.Equals(v, value).ExtractMostSignificantBits());

    // Points 0–3 and second–second+3 of an interleaved array into x and z lanes.
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    private static void Split(ref float points, int count, out Vector256<float> x, out Vector256<float> z)
    {
        Vector256<float> low, high;
        if (count >= 4)
        {
            low = Vector256.LoadUnsafe(ref points);
            high = Vector256.LoadUnsafe(ref points, (nuint)(2 * (count - 4)));
        }
        else
        {
            // x0 z0 x1 z1 | x2 z2 x2 z2
            var first = Vector128.LoadUnsafe(ref points);
            var last = Vector128.Create(Unsafe.As<float, long>(ref Unsafe.Add(ref points, 4))).AsSingle();
            low = Vector256.Create(first, last);
            high = low;
        }

        // Per 128-bit half: (x0 x1 xs xs+1 | x2 x3 xs+2 xs+3), then the 64-bit pairs in order.
        var xs = Avx.Shuffle(low, high, 0b10_00_10_00);
        var zs = Avx.Shuffle(low, high, 0b11_01_11_01);
        x = Avx2.Permute4x64(xs.AsDouble(), 0b11_01_10_00).AsSingle();
        z = Avx2.Permute4x64(zs.AsDouble(), 0b11_01_10_00).AsSingle();
    }

    private static int[] BuildNextTable()
    {
        var table = new int[8 * 6];
        for (int count = 3; count <= 8; count++)
        {
            for (int lane = 0; lane < 8; lane++)
            {
                int next = (Index(lane, count) + 1) % count;
                table[(8 * (count - 3)) + lane] = Lane(next, count);
            }
        }

        return table;
    }
}
