namespace URWPGSim2D.Server.Json;

/// <summary>
/// Paths into the input as users read them: the serializer's <c>$[3].a.vertices[2]</c> becomes
/// <c>pairs[3].a.vertices[2]</c>, the root <c>$</c> taking the name of the input (<c>pairs</c>).
/// </summary>
internal static class InputPath
{
    /// <summary>Splits a System.Text.Json path (<c>$</c>, then <c>.name</c>, <c>['name']</c> or <c>[index]</c> steps).</summary>
    /// <param name="serializerPath">The path of a <see cref="System.Text.Json.JsonException"/>.</param>
    /// <returns>The steps after the root, or null when the path is missing or not of that form.</returns>
    public static JsonPathSegment[]? Parse(string? serializerPath)
    {
        if (serializerPath is null || !serializerPath.StartsWith('$'))
        {
            return null;
        }

        var segments = new List<JsonPathSegment>();
        string p = serializerPath;
        int i = 1;
        while (i < p.Length)
        {
            if (p[i] == '.')
            {
                int end = p.IndexOfAny(['.', '['], i + 1);
                end = end < 0 ? p.Length : end;
                if (end == i + 1)
                {
                    return null;
                }

                segments.Add(JsonPathSegment.Property(p[(i + 1)..end]));
                i = end;
            }
            else if (p.AsSpan(i).StartsWith("['", StringComparison.Ordinal))
            {
                int end = p.IndexOf("']", i + 2, StringComparison.Ordinal);
                if (end < 0)
                {
                    return null;
                }

                segments.Add(JsonPathSegment.Property(p[(i + 2)..end]));
                i = end + 2;
            }
            else if (p[i] == '[')
            {
                int end = p.IndexOf(']', i + 1);
                if (end < 0 || !int.TryParse(p.AsSpan(i + 1, end - i - 1), NumberStyles.None, CultureInfo.InvariantCulture, out int index))
                {
                    return null;
                }

                segments.Add(JsonPathSegment.Element(index));
                i = end + 1;
            }
            else
            {
                return null;
            }
        }

        return [.. segments];
    }

    /// <summary>Writes a path with the given root name: <c>pairs[3].a.radius</c>.</summary>
    /// <param name="rootName">The name of the whole input, e.g. <c>pairs</c>.</param>
    /// <param name="segments">The steps after the root.</param>
    /// <returns>The user-facing path.</returns>
    public static string Format(string rootName, ReadOnlySpan<JsonPathSegment> segments)
    {
        var text = new StringBuilder(rootName);
        foreach (var s in segments)
        {
            if (s.IsIndex)
            {
                text.Append('[').Append(s.Index.ToString(CultureInfo.InvariantCulture)).Append(']');
            }
            else
            {
                text.Append('.').Append(s.Name);
            }
        }

        return text.ToString();
    }

    /// <summary>The user-facing form of a serializer path; the root name alone when the path is unknown.</summary>
    /// <param name="serializerPath">The path of a <see cref="System.Text.Json.JsonException"/>.</param>
    /// <param name="rootName">The name of the whole input.</param>
    /// <returns>E.g. <c>pairs[3].a.radius</c>.</returns>
    public static string FromSerializerPath(string? serializerPath, string rootName)
    {
        var segments = Parse(serializerPath);
        if (segments is not null)
        {
            return Format(rootName, segments);
        }

        return serializerPath is { Length: > 0 } && serializerPath[0] == '$' ? rootName + serializerPath[1..] : rootName;
    }
}
