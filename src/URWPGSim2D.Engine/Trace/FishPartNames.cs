using URWPGSim2D.Collision.Fish;

namespace URWPGSim2D.Engine.Trace;

/// <summary>
/// The names of the eight <see cref="FishPart"/>s in the program's JSON (collide's <c>partA</c> /
/// <c>partB</c>, the keys of <c>shapes</c>' <c>leaves</c>, the trace): the enum names in camelCase.
/// </summary>
public static class FishPartNames
{
    private static readonly string[] Names = ["leftPectoral", "body", "rightPectoral", "tail1", "tail2", "tail3", "leftCaudal", "rightCaudal"];

    /// <summary>The camelCase name of a part, e.g. <c>leftPectoral</c>.</summary>
    /// <param name="part">One of the eight parts.</param>
    /// <returns>Its name.</returns>
    /// <exception cref="ArgumentOutOfRangeException"><paramref name="part"/> is not one of the eight parts.</exception>
    public static string Of(FishPart part) =>
        (uint)part < (uint)Names.Length ? Names[(int)part] : throw new ArgumentOutOfRangeException(nameof(part), part, "not a fish part");

    /// <summary>The name of a part, or null for no part (a side that is not a fish, or no contact).</summary>
    /// <param name="part">A part or null.</param>
    /// <returns>Its name or null.</returns>
    public static string? OfOptional(FishPart? part) => part is { } p ? Of(p) : null;
}
