using System;

namespace URWPGSim2D.Server.Json;

/// <summary>
/// The JSON kind each SHAPE field holds, for "expected ..." messages when a well-formed value
/// has the wrong kind (a string where a number belongs).
/// </summary>
internal static class ShapeSchema
{
    /// <summary>What is expected at a path inside a SHAPE object.</summary>
    /// <param name="inShape">The steps after the SHAPE object (empty: the object itself).</param>
    /// <returns>A phrase such as "a number", or null for a path that is not part of the format.</returns>
    public static string? ExpectedKind(ReadOnlySpan<JsonPathSegment> inShape)
    {
        if (inShape.IsEmpty)
        {
            return "a shape object {\"type\": ..., ...}";
        }

        if (inShape[0].IsIndex)
        {
            return null;
        }

        int depth = inShape.Length - 1;
        foreach (var step in inShape[1..])
        {
            if (!step.IsIndex)
            {
                return null;
            }
        }

        return (inShape[0].Name, depth) switch
        {
            ("type", 0) => "a string",
            ("radius", 0) => "a number",
            ("center" or "a" or "b", 0) => "an array of 2 numbers [x, z]",
            ("min" or "max", 0) => "an array of numbers",
            ("vertices", 0) => "an array of [x, z] points",
            ("vertices", 1) => "an array of 2 numbers [x, z]",
            ("center" or "a" or "b" or "min" or "max", 1) or ("vertices", 2) => "a number",
            _ => null,
        };
    }
}
