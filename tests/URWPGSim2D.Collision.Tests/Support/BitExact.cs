namespace URWPGSim2D.Collision.Tests.Support;

/// <summary>
/// Bit-for-bit comparison of results, for the tests that hold two paths of a kernel to the same
/// floats, the sign of a zero included (a last-bit difference can change a match).
/// </summary>
public static class BitExact
{
    /// <summary>Fails unless both results have the same intersection flag and the same bits in every float.</summary>
    public static void AssertSame(in CollisionDetectionResult expected, in CollisionDetectionResult actual)
    {
        if (expected.Intersect != actual.Intersect)
        {
            throw new XunitException($"intersect: expected {expected.Intersect}, got {actual.Intersect}");
        }

        AssertSame(expected.MinimumTranslationVector, actual.MinimumTranslationVector, "MTV");
        AssertSame(expected.NormalAxis, actual.NormalAxis, "normal");
        AssertSame(expected.ActionPoint, actual.ActionPoint, "action point");
    }

    /// <summary>Fails unless the two vectors have the same bits; <paramref name="what"/> names them in the message.</summary>
    public static void AssertSame(Vector3 expected, Vector3 actual, string what)
    {
        if (Bits(expected) != Bits(actual))
        {
            throw new XunitException($"{what}: expected {Hex(expected)}, got {Hex(actual)}");
        }
    }

    /// <summary>The bits of the three floats.</summary>
    public static (int X, int Y, int Z) Bits(Vector3 v) =>
        (BitConverter.SingleToInt32Bits(v.X), BitConverter.SingleToInt32Bits(v.Y), BitConverter.SingleToInt32Bits(v.Z));

    private static string Hex(Vector3 v) => $"{v} [{Bits(v).X:X8} {Bits(v).Y:X8} {Bits(v).Z:X8}]";
}
