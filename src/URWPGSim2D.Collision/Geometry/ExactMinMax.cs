namespace URWPGSim2D.Collision.Geometry;

/// <summary>
/// <see cref="MathF.Min(float, float)"/> and <see cref="MathF.Max(float, float)"/>
/// bit for bit for operands that are not NaN, in two vector instructions instead of the IEEE
/// fix-up sequence those compile to (three dependent instructions on AVX-512). The hardware
/// minimum returns its second operand when the two compare equal; taking it both ways round and
/// combining the bits gives −0 for min(−0, +0) and +0 for max(−0, +0), as MathF does, and the
/// common value otherwise. Without vector hardware: MathF itself.
/// </summary>
internal static class ExactMinMax
{
    /// <summary>MathF.Min(a, b) for a, b not NaN.</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static float Min(float a, float b)
    {
        if (!Vector128.IsHardwareAccelerated)
        {
            return MathF.Min(a, b);
        }

        var x = Vector128.CreateScalarUnsafe(a);
        var y = Vector128.CreateScalarUnsafe(b);
        return (Vector128.MinNative(x, y) | Vector128.MinNative(y, x)).ToScalar();
    }

    /// <summary>MathF.Max(a, b) for a, b not NaN.</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static float Max(float a, float b)
    {
        if (!Vector128.IsHardwareAccelerated)
        {
            return MathF.Max(a, b);
        }

        var x = Vector128.CreateScalarUnsafe(a);
        var y = Vector128.CreateScalarUnsafe(b);
        return (Vector128.MaxNative(x, y) & Vector128.MaxNative(y, x)).ToScalar();
    }
}
