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

        if (inShape[0].Name == "size")
        {
            return SizeExpectedKind(inShape[1..]);
        }

        if (!OnlyIndices(inShape[1..]))
        {
            return null;
        }

        int depth = inShape.Length - 1;
        return (inShape[0].Name, depth) switch
        {
            ("type", 0) => "a string",
            ("radius" or "heading", 0) => "a number",
            ("center" or "a" or "b" or "position", 0) => "an array of 2 numbers [x, z]",
            ("min" or "max", 0) => "an array of numbers",
            ("joints", 0) => $"an array of 3 numbers {FishJson.JointAnglesForm}",
            ("vertices", 0) => "an array of [x, z] points",
            ("vertices", 1) => "an array of 2 numbers [x, z]",
            ("center" or "a" or "b" or "min" or "max" or "position" or "joints", 1) or ("vertices", 2) => "a number",
            _ => null,
        };
    }

    // The fish's "size" object: {"length": L, "width": W, "head": H, "joints": [L1, L2, L3]}.
    private static string? SizeExpectedKind(ReadOnlySpan<JsonPathSegment> inSize)
    {
        if (inSize.IsEmpty)
        {
            return $"an object {{\"length\": L, \"width\": W, \"head\": H, \"joints\": {FishJson.JointLengthsForm}}}";
        }

        if (inSize[0].IsIndex || !OnlyIndices(inSize[1..]))
        {
            return null;
        }

        return (inSize[0].Name, inSize.Length - 1) switch
        {
            ("length" or "width" or "head", 0) or ("joints", 1) => "a number",
            ("joints", 0) => $"an array of 3 numbers {FishJson.JointLengthsForm}",
            _ => null,
        };
    }

    private static bool OnlyIndices(ReadOnlySpan<JsonPathSegment> steps)
    {
        foreach (var step in steps)
        {
            if (!step.IsIndex)
            {
                return false;
            }
        }

        return true;
    }
}
