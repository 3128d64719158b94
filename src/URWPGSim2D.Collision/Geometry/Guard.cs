using System.Diagnostics.CodeAnalysis;
using System.Runtime.CompilerServices;

namespace URWPGSim2D.Collision.Geometry;

/// <summary>
/// Argument checks shared by every shape constructor: the message names the value. The checks
/// inline where they are made; the messages are built out of line, only when one fails.
/// </summary>
internal static class Guard
{
    public static void Finite(float value, string paramName)
    {
        if (!float.IsFinite(value))
        {
            NotFinite(value, paramName);
        }
    }

    public static void Finite(Vector2 value, string paramName)
    {
        if (!float.IsFinite(value.X) || !float.IsFinite(value.Y))
        {
            NotFinite(value, paramName);
        }
    }

    public static void Positive(float value, string paramName)
    {
        if (!(value > 0f) || !float.IsFinite(value))
        {
            NotPositive(value, paramName);
        }
    }

    [DoesNotReturn]
    [MethodImpl(MethodImplOptions.NoInlining)]
    private static void NotFinite(float value, string paramName) =>
        throw new ArgumentException($"must be a finite number, got {value}", paramName);

    [DoesNotReturn]
    [MethodImpl(MethodImplOptions.NoInlining)]
    private static void NotFinite(Vector2 value, string paramName) =>
        throw new ArgumentException($"must have finite coordinates, got [{value.X}, {value.Y}]", paramName);

    [DoesNotReturn]
    [MethodImpl(MethodImplOptions.NoInlining)]
    private static void NotPositive(float value, string paramName) =>
        throw new ArgumentException(float.IsFinite(value) ? $"must be > 0, got {value}" : $"must be a finite number, got {value}", paramName);
}
