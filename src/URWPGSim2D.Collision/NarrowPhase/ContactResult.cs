using System.Runtime.InteropServices;
using System.Runtime.Intrinsics.X86;

namespace URWPGSim2D.Collision.NarrowPhase;

/// <summary>
/// Builds an intersecting <see cref="CollisionDetectionResult"/> from plane quantities, as
/// <see cref="CollisionDetectionResult.FromPlane"/> does, bit for bit, but by assembling its 40
/// bytes in two 16-byte vectors and one 8-byte store (six shuffles) instead of building and
/// re-building three <see cref="Vector3"/>s (about twenty instructions fewer at the end of every
/// pair test). The field offsets are checked once against the constructor; a runtime that lays
/// the result out differently, or a machine without SSE4.1, gets the constructor.
/// </summary>
internal static class ContactResult
{
    // Intersect at 0 (with 3 padding bytes), the MTV at 4, the normal at 16, the action point at 28.
    private static readonly bool Direct = LaidOutAsExpected();

    /// <summary>The result for a contact along <paramref name="normal"/> (unit, plane vector) of <paramref name="depth"/> at <paramref name="point"/>.</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static CollisionDetectionResult Plane(Vector2 normal, float depth, Vector2 point)
    {
        if (!Direct || !Sse41.IsSupported)
        {
            return CollisionDetectionResult.FromPlane(normal, depth, point);
        }

        var zero = Vector128<float>.Zero;
        var n = normal.AsVector128Unsafe();
        var mtv = Sse.UnpackLow(n * depth, zero);                                                          // mtv.x 0 mtv.z 0
        Fields fields;
        fields.A = Vector128.Create(1, 0, 0, 0).AsSingle() | Sse2.ShiftLeftLogical128BitLane(mtv.AsByte(), 4).AsSingle(); // true mtv.x 0 mtv.z
        fields.B = Sse41.Insert(Sse.UnpackLow(n, zero), point.AsVector128Unsafe(), 0b00_11_0000);          // n.x 0 n.z point.x
        fields.C = Sse41.Insert(zero, point.AsVector128Unsafe(), 0b01_01_0000).AsDouble().ToScalar();       // 0 point.z, as one 8-byte store
        return Unsafe.BitCast<Fields, CollisionDetectionResult>(fields);
    }

    /// <summary>
    /// <see cref="Plane"/> for a normal and a point already laid out as the world's x, 0, z, 0
    /// (the two zero lanes +0): no shuffle to spread them, three instructions fewer.
    /// </summary>
    /// <param name="normal">The unit normal: x, +0, z, +0.</param>
    /// <param name="depth">The depth along the normal.</param>
    /// <param name="point">The action point: x, +0, z, +0.</param>
    /// <returns>The intersecting result.</returns>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static CollisionDetectionResult World(Vector128<float> normal, float depth, Vector128<float> point)
    {
        if (!Direct || !Sse41.IsSupported)
        {
            return CollisionDetectionResult.FromPlane(new Vector2(normal.ToScalar(), normal.GetElement(2)), depth, new Vector2(point.ToScalar(), point.GetElement(2)));
        }

        // mtv.x ? mtv.z ? moved up a lane, then true and 0 blended into lanes 0 and 2 (a product
        // 0·depth can be −0: the blend, unlike an or, does not keep its sign).
        var mtv = Sse2.ShiftLeftLogical128BitLane((normal * depth).AsByte(), 4).AsSingle();              // 0 mtv.x ? mtv.z
        Fields fields;
        fields.A = Sse41.Blend(mtv, Vector128.Create(1, 0, 0, 0).AsSingle(), 0b0101);                     // true mtv.x 0 mtv.z
        fields.B = Sse41.Insert(normal, point, 0b00_11_0000);                                             // n.x 0 n.z point.x
        fields.C = Sse2.ShiftRightLogical128BitLane(point.AsByte(), 4).AsDouble().ToScalar();            // 0 point.z
        return Unsafe.BitCast<Fields, CollisionDetectionResult>(fields);
    }

    // The result's bytes: (intersect, mtv.x, 0, mtv.z), (normal.x, 0, normal.z, point.x), (0, point.z).
    [StructLayout(LayoutKind.Explicit, Size = 40)]
    private struct Fields
    {
        [FieldOffset(0)]
        public Vector128<float> A;
        [FieldOffset(16)]
        public Vector128<float> B;
        // Two floats' bits (a double keeps them in a vector register: a Vector64 went through the stack).
        [FieldOffset(32)]
        public double C;
    }

    private static bool LaidOutAsExpected()
    {
        if (Unsafe.SizeOf<CollisionDetectionResult>() != 40)
        {
            return false;
        }

        var probe = new CollisionDetectionResult(true, new Vector3(1f, 0f, 2f), new Vector3(3f, 0f, 4f), new Vector3(5f, 0f, 6f));
        ref byte b = ref Unsafe.As<CollisionDetectionResult, byte>(ref probe);
        return Unsafe.ReadUnaligned<byte>(ref b) == 1
            && Unsafe.ReadUnaligned<Vector3>(ref Unsafe.Add(ref b, 4)) == new Vector3(1f, 0f, 2f)
            && Unsafe.ReadUnaligned<Vector3>(ref Unsafe.Add(ref b, 16)) == new Vector3(3f, 0f, 4f)
            && Unsafe.ReadUnaligned<Vector3>(ref Unsafe.Add(ref b, 28)) == new Vector3(5f, 0f, 6f);
    }
}
