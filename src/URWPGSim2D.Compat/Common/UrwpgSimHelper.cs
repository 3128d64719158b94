using Xna = Microsoft.Xna.Framework;

namespace URWPGSim2D.Common;

/// <summary>The original's small helpers: extremes with their index, and frame transformations.</summary>
public static partial class UrwpgSimHelper
{
    /// <summary>Largest of four values and its index (the first on ties).</summary>
    /// <param name="value1">Value 0.</param>
    /// <param name="value2">Value 1.</param>
    /// <param name="value3">Value 2.</param>
    /// <param name="value4">Value 3.</param>
    /// <param name="seq">Index 0..3 of the largest.</param>
    /// <returns>The largest value.</returns>
    public static int Max(int value1, int value2, int value3, int value4, ref int seq) => Extreme([value1, value2, value3, value4], +1, ref seq);

    /// <summary>Smallest of four values and its index (the first on ties).</summary>
    /// <param name="value1">Value 0.</param>
    /// <param name="value2">Value 1.</param>
    /// <param name="value3">Value 2.</param>
    /// <param name="value4">Value 3.</param>
    /// <param name="seq">Index 0..3 of the smallest.</param>
    /// <returns>The smallest value.</returns>
    public static int Min(int value1, int value2, int value3, int value4, ref int seq) => Extreme([value1, value2, value3, value4], -1, ref seq);

    /// <summary>Largest of four values and its index (the first on ties).</summary>
    /// <param name="value1">Value 0.</param>
    /// <param name="value2">Value 1.</param>
    /// <param name="value3">Value 2.</param>
    /// <param name="value4">Value 3.</param>
    /// <param name="seq">Index 0..3 of the largest.</param>
    /// <returns>The largest value.</returns>
    public static float Max(float value1, float value2, float value3, float value4, ref int seq) => Extreme([value1, value2, value3, value4], +1, ref seq);

    /// <summary>Smallest of four values and its index (the first on ties).</summary>
    /// <param name="value1">Value 0.</param>
    /// <param name="value2">Value 1.</param>
    /// <param name="value3">Value 2.</param>
    /// <param name="value4">Value 3.</param>
    /// <param name="seq">Index 0..3 of the smallest.</param>
    /// <returns>The smallest value.</returns>
    public static float Min(float value1, float value2, float value3, float value4, ref int seq) => Extreme([value1, value2, value3, value4], -1, ref seq);

    /// <summary>Largest of five values and its index (the first on ties).</summary>
    /// <param name="value1">Value 0.</param>
    /// <param name="value2">Value 1.</param>
    /// <param name="value3">Value 2.</param>
    /// <param name="value4">Value 3.</param>
    /// <param name="value5">Value 4.</param>
    /// <param name="seq">Index 0..4 of the largest.</param>
    /// <returns>The largest value.</returns>
    public static float Max(float value1, float value2, float value3, float value4, float value5, ref int seq) =>
        Extreme([value1, value2, value3, value4, value5], +1, ref seq);

    /// <summary>Smallest of five values and its index (the first on ties).</summary>
    /// <param name="value1">Value 0.</param>
    /// <param name="value2">Value 1.</param>
    /// <param name="value3">Value 2.</param>
    /// <param name="value4">Value 3.</param>
    /// <param name="value5">Value 4.</param>
    /// <param name="seq">Index 0..4 of the smallest.</param>
    /// <returns>The smallest value.</returns>
    public static float Min(float value1, float value2, float value3, float value4, float value5, ref int seq) =>
        Extreme([value1, value2, value3, value4, value5], -1, ref seq);

    /// <summary>Largest of seven values and its index (the first on ties).</summary>
    /// <param name="value1">Value 0.</param>
    /// <param name="value2">Value 1.</param>
    /// <param name="value3">Value 2.</param>
    /// <param name="value4">Value 3.</param>
    /// <param name="value5">Value 4.</param>
    /// <param name="value6">Value 5.</param>
    /// <param name="value7">Value 6.</param>
    /// <param name="seq">Index 0..6 of the largest.</param>
    /// <returns>The largest value.</returns>
    public static float Max(float value1, float value2, float value3, float value4, float value5, float value6, float value7, ref int seq) =>
        Extreme([value1, value2, value3, value4, value5, value6, value7], +1, ref seq);

    /// <summary>Smallest of seven values and its index (the first on ties).</summary>
    /// <param name="value1">Value 0.</param>
    /// <param name="value2">Value 1.</param>
    /// <param name="value3">Value 2.</param>
    /// <param name="value4">Value 3.</param>
    /// <param name="value5">Value 4.</param>
    /// <param name="value6">Value 5.</param>
    /// <param name="value7">Value 6.</param>
    /// <param name="seq">Index 0..6 of the smallest.</param>
    /// <returns>The smallest value.</returns>
    public static float Min(float value1, float value2, float value3, float value4, float value5, float value6, float value7, ref int seq) =>
        Extreme([value1, value2, value3, value4, value5, value6, value7], -1, ref seq);

    /// <summary>
    /// A point given in a local frame (origin, X axis at angle <paramref name="theta"/>) expressed in
    /// field coordinates: world = origin + R(θ)·local.
    /// </summary>
    /// <param name="theta">Direction of the local X axis in the field, rad.</param>
    /// <param name="xLocalOri">Field X of the local origin.</param>
    /// <param name="zLocalOri">Field Z of the local origin.</param>
    /// <param name="xLocal">Local X of the point.</param>
    /// <param name="zLocal">Local Z of the point.</param>
    /// <param name="xWorld">Field X of the point.</param>
    /// <param name="zWorld">Field Z of the point.</param>
    public static void CoordinateTransformation(float theta, float xLocalOri, float zLocalOri, float xLocal, float zLocal, ref float xWorld, ref float zWorld)
    {
        float cos = MathF.Cos(theta), sin = MathF.Sin(theta);
        xWorld = (xLocal * cos) - (zLocal * sin) + xLocalOri;
        zWorld = (xLocal * sin) + (zLocal * cos) + zLocalOri;
    }

    /// <summary>A local point expressed in field coordinates (X and Z of <paramref name="world"/> are written).</summary>
    /// <param name="theta">Direction of the local X axis in the field, rad.</param>
    /// <param name="localOri">Field position of the local origin.</param>
    /// <param name="local">The point in the local frame.</param>
    /// <param name="world">The point in the field.</param>
    public static void CoordinateTransformation(float theta, Xna.Vector3 localOri, Xna.Vector3 local, ref Xna.Vector3 world) =>
        CoordinateTransformation(theta, localOri.X, localOri.Z, local.X, local.Z, ref world.X, ref world.Z);

    /// <summary>
    /// A field point expressed in a local frame (origin, X axis at angle <paramref name="theta"/>):
    /// local = R(−θ)·(world − origin).
    /// </summary>
    /// <param name="theta">Direction of the local X axis in the field, rad.</param>
    /// <param name="xLocalOri">Field X of the local origin.</param>
    /// <param name="zLocalOri">Field Z of the local origin.</param>
    /// <param name="xLocal">Local X of the point.</param>
    /// <param name="zLocal">Local Z of the point.</param>
    /// <param name="xWorld">Field X of the point.</param>
    /// <param name="zWorld">Field Z of the point.</param>
    public static void CoordinateTransformation(float theta, float xLocalOri, float zLocalOri, ref float xLocal, ref float zLocal, float xWorld, float zWorld)
    {
        float cos = MathF.Cos(theta), sin = MathF.Sin(theta);
        float dx = xWorld - xLocalOri, dz = zWorld - zLocalOri;
        xLocal = (dx * cos) + (dz * sin);
        zLocal = (dz * cos) - (dx * sin);
    }

    /// <summary>A field point expressed in a local frame (X and Z of <paramref name="local"/> are written).</summary>
    /// <param name="theta">Direction of the local X axis in the field, rad.</param>
    /// <param name="localOri">Field position of the local origin.</param>
    /// <param name="local">The point in the local frame.</param>
    /// <param name="world">The point in the field.</param>
    public static void CoordinateTransformation(float theta, Xna.Vector3 localOri, ref Xna.Vector3 local, Xna.Vector3 world) =>
        CoordinateTransformation(theta, localOri.X, localOri.Z, ref local.X, ref local.Z, world.X, world.Z);

    private static T Extreme<T>(ReadOnlySpan<T> values, int sign, ref int seq)
        where T : IComparable<T>
    {
        T best = values[0];
        seq = 0;
        for (int i = 1; i < values.Length; i++)
        {
            if (values[i].CompareTo(best) * sign > 0)
            {
                best = values[i];
                seq = i;
            }
        }

        return best;
    }
}
