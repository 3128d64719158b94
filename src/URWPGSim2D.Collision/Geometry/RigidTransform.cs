using System.Runtime.InteropServices;

namespace URWPGSim2D.Collision.Geometry;

/// <summary>
/// Rotating and moving packed plane points: world = origin + R(α)·local with
/// R(α)·(a, b) = (a·cos α − b·sin α, a·sin α + b·cos α). Four points per 256-bit vector (or two
/// per 128-bit vector) where the hardware has them; every lane does the same multiplications and
/// additions in the same order as <see cref="Rotate"/>, so all paths give bit-identical results.
/// </summary>
internal static class RigidTransform
{
    /// <summary>R(α)·local, with <paramref name="rotation"/> = (cos α, sin α).</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static Vector2 Rotate(Vector2 rotation, Vector2 local) =>
        new(local.X * rotation.X - local.Y * rotation.Y, local.X * rotation.Y + local.Y * rotation.X);

    /// <summary>world[i] = origin + R(α)·local[i] (the two spans have the same length).</summary>
    public static void Place(ReadOnlySpan<Vector2> local, Span<Vector2> world, Vector2 origin, Vector2 rotation) =>
        Transform(local, world, Vector2.Zero, origin, rotation, shift: false, translate: true);

    /// <summary>
    /// world[i] = origin + R(α)·(local[i] − pivot): points turned about <paramref name="pivot"/> and
    /// moved to <paramref name="origin"/>, with the subtraction done first (the two spans have the same length).
    /// </summary>
    public static void PlaceAbout(ReadOnlySpan<Vector2> local, Span<Vector2> world, Vector2 pivot, Vector2 origin, Vector2 rotation) =>
        Transform(local, world, pivot, origin, rotation, shift: true, translate: true);

    /// <summary>world[i] = R(α)·local[i]: directions such as edge normals (no translation).</summary>
    public static void Turn(ReadOnlySpan<Vector2> local, Span<Vector2> world, Vector2 rotation) =>
        Transform(local, world, Vector2.Zero, Vector2.Zero, rotation, shift: false, translate: false);

    /// <summary>
    /// One rigid frame at once: its points placed (<see cref="Place"/>) and its directions turned
    /// (<see cref="Turn"/>); the four spans have the same length.
    /// </summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static void PlaceAndTurn(ReadOnlySpan<Vector2> localPoints, ReadOnlySpan<Vector2> localDirections, Span<Vector2> points, Span<Vector2> directions, Vector2 origin, Vector2 rotation)
    {
        Transform(localPoints, points, Vector2.Zero, origin, rotation, shift: false, translate: true);
        Transform(localDirections, directions, Vector2.Zero, Vector2.Zero, rotation, shift: false, translate: false);
    }

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    private static void Transform(ReadOnlySpan<Vector2> local, Span<Vector2> world, Vector2 pivot, Vector2 origin, Vector2 rotation, bool shift, bool translate)
    {
        if (world.Length < local.Length)
        {
            throw new ArgumentException($"destination holds {world.Length} points, {local.Length} needed", nameof(world));
        }

        int i = 0;
        ref float src = ref Unsafe.As<Vector2, float>(ref MemoryMarshal.GetReference(local));
        ref float dst = ref Unsafe.As<Vector2, float>(ref MemoryMarshal.GetReference(world));
        if (Vector256.IsHardwareAccelerated && local.Length >= 4)
        {
            // Four points per vector; the last block overlaps the one before (same values written twice).
            var cos = Vector256.Create(rotation.X);
            var sin = Vector256.Create(-rotation.Y, rotation.Y, -rotation.Y, rotation.Y, -rotation.Y, rotation.Y, -rotation.Y, rotation.Y);
            var o = Vector256.Create(origin.X, origin.Y, origin.X, origin.Y, origin.X, origin.Y, origin.X, origin.Y);
            var p = Vector256.Create(pivot.X, pivot.Y, pivot.X, pivot.Y, pivot.X, pivot.Y, pivot.X, pivot.Y);
            for (int at = 0; ; at += 4)
            {
                at = Math.Min(at, local.Length - 4);
                var v = Vector256.LoadUnsafe(ref src, (nuint)(2 * at));
                v = shift ? v - p : v;
                var turned = (v * cos) + (Vector256.Shuffle(v, Vector256.Create(1, 0, 3, 2, 5, 4, 7, 6)) * sin);
                (translate ? o + turned : turned).StoreUnsafe(ref dst, (nuint)(2 * at));
                if (at == local.Length - 4)
                {
                    return;
                }
            }
        }

        if (Vector128.IsHardwareAccelerated)
        {
            var cos = Vector128.Create(rotation.X);
            var sin = Vector128.Create(-rotation.Y, rotation.Y, -rotation.Y, rotation.Y);
            var o = Vector128.Create(origin.X, origin.Y, origin.X, origin.Y);
            var p = Vector128.Create(pivot.X, pivot.Y, pivot.X, pivot.Y);
            for (; i + 2 <= local.Length; i += 2)
            {
                var v = Vector128.LoadUnsafe(ref src, (nuint)(2 * i));
                v = shift ? v - p : v;
                var turned = (v * cos) + (Vector128.Shuffle(v, Vector128.Create(1, 0, 3, 2)) * sin);
                (translate ? o + turned : turned).StoreUnsafe(ref dst, (nuint)(2 * i));
            }
        }

        for (; i < local.Length; i++)
        {
            Vector2 v = shift ? local[i] - pivot : local[i];
            world[i] = translate ? origin + Rotate(rotation, v) : Rotate(rotation, v);
        }
    }
}
