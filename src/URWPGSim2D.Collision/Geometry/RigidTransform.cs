using System;
using System.Numerics;
using System.Runtime.CompilerServices;
using System.Runtime.InteropServices;
using System.Runtime.Intrinsics;

namespace URWPGSim2D.Collision.Geometry;

/// <summary>
/// Rotating and moving packed plane points: world = origin + R(α)·local with
/// R(α)·(a, b) = (a·cos α − b·sin α, a·sin α + b·cos α). Two points per 128-bit vector where
/// the hardware has one; every lane does the same multiplications and additions in the same
/// order as <see cref="Rotate"/>, so both paths give bit-identical results.
/// </summary>
internal static class RigidTransform
{
    /// <summary>R(α)·local, with <paramref name="rotation"/> = (cos α, sin α).</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static Vector2 Rotate(Vector2 rotation, Vector2 local) =>
        new(local.X * rotation.X - local.Y * rotation.Y, local.X * rotation.Y + local.Y * rotation.X);

    /// <summary>world[i] = origin + R(α)·local[i] (the two spans have the same length).</summary>
    public static void Place(ReadOnlySpan<Vector2> local, Span<Vector2> world, Vector2 origin, Vector2 rotation)
    {
        if (world.Length < local.Length)
        {
            throw new ArgumentException($"destination holds {world.Length} points, {local.Length} needed", nameof(world));
        }

        int i = 0;
        if (Vector128.IsHardwareAccelerated)
        {
            ref float src = ref Unsafe.As<Vector2, float>(ref MemoryMarshal.GetReference(local));
            ref float dst = ref Unsafe.As<Vector2, float>(ref MemoryMarshal.GetReference(world));
            var cos = Vector128.Create(rotation.X);
            var sin = Vector128.Create(-rotation.Y, rotation.Y, -rotation.Y, rotation.Y);
            var o = Vector128.Create(origin.X, origin.Y, origin.X, origin.Y);
            for (; i + 2 <= local.Length; i += 2)
            {
                var v = Vector128.LoadUnsafe(ref src, (nuint)(2 * i));
                var swapped = Vector128.Shuffle(v, Vector128.Create(1, 0, 3, 2));
                (o + ((v * cos) + (swapped * sin))).StoreUnsafe(ref dst, (nuint)(2 * i));
            }
        }

        for (; i < local.Length; i++)
        {
            world[i] = origin + Rotate(rotation, local[i]);
        }
    }

    /// <summary>world[i] = R(α)·local[i]: directions such as edge normals (no translation).</summary>
    public static void Turn(ReadOnlySpan<Vector2> local, Span<Vector2> world, Vector2 rotation)
    {
        if (world.Length < local.Length)
        {
            throw new ArgumentException($"destination holds {world.Length} points, {local.Length} needed", nameof(world));
        }

        int i = 0;
        if (Vector128.IsHardwareAccelerated)
        {
            ref float src = ref Unsafe.As<Vector2, float>(ref MemoryMarshal.GetReference(local));
            ref float dst = ref Unsafe.As<Vector2, float>(ref MemoryMarshal.GetReference(world));
            var cos = Vector128.Create(rotation.X);
            var sin = Vector128.Create(-rotation.Y, rotation.Y, -rotation.Y, rotation.Y);
            for (; i + 2 <= local.Length; i += 2)
            {
                var v = Vector128.LoadUnsafe(ref src, (nuint)(2 * i));
                var swapped = Vector128.Shuffle(v, Vector128.Create(1, 0, 3, 2));
                ((v * cos) + (swapped * sin)).StoreUnsafe(ref dst, (nuint)(2 * i));
            }
        }

        for (; i < local.Length; i++)
        {
            world[i] = Rotate(rotation, local[i]);
        }
    }
}
