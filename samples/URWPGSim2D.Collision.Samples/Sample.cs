using System;
using System.Globalization;

namespace URWPGSim2D.Collision.Samples;

/// <summary>
/// The checks a sample makes of its own results, so CI running the samples proves what the docs
/// say (not only that the code compiles). A failed check throws; <c>Program</c> reports it.
/// </summary>
/// <remarks>
/// How a docs example is tied to its sample: the Markdown has a line
/// <c>&lt;!-- sample: samples/PROJECT/FILE.cs --&gt;</c> right before the code block, and the block
/// is the text between the file's <c>// &lt;snippet&gt;</c> and <c>// &lt;/snippet&gt;</c> lines
/// (each region de-indented, regions joined by one blank line).
/// </remarks>
internal static class Sample
{
    /// <summary>Fails unless <paramref name="condition"/> holds.</summary>
    public static void Check(bool condition, string what)
    {
        if (!condition)
        {
            throw new InvalidOperationException($"expected: {what}");
        }
    }

    /// <summary>Fails unless <paramref name="actual"/> is within 1e-3 of <paramref name="expected"/>.</summary>
    public static void Near(float actual, float expected, string what)
    {
        if (!(MathF.Abs(actual - expected) <= 1e-3f))
        {
            throw new InvalidOperationException(string.Create(CultureInfo.InvariantCulture, $"{what}: expected {expected}, got {actual}"));
        }
    }
}
