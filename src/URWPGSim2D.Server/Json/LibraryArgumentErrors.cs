namespace URWPGSim2D.Server.Json;

/// <summary>
/// Turns the library's validation errors into input errors. The library throws
/// <see cref="ArgumentException"/> whose <see cref="ArgumentException.ParamName"/> is a
/// constructor parameter, possibly with an index (<c>vertices[3]</c>, <c>min[2]</c>); each shape
/// reader supplies the JSON field that feeds each parameter.
/// </summary>
internal static class LibraryArgumentErrors
{
    /// <summary>Maps a library error to <c>SHAPE.FIELD[index]: message</c>.</summary>
    /// <param name="error">The library's exception.</param>
    /// <param name="shapePath">The path of the shape object, e.g. <c>pairs[3].a</c>.</param>
    /// <param name="fieldByParameter">Library parameter name → JSON field name, for this shape type.</param>
    /// <returns>The input error; it names the shape itself if the parameter is not in the table.</returns>
    public static InputException ToInputError(ArgumentException error, string shapePath, IReadOnlyDictionary<string, string> fieldByParameter)
    {
        string? parameter = error.ParamName;
        string path = shapePath;
        if (parameter is not null)
        {
            int bracket = parameter.IndexOf('[');
            string root = bracket < 0 ? parameter : parameter[..bracket];
            string suffix = bracket < 0 ? string.Empty : parameter[bracket..];
            if (fieldByParameter.TryGetValue(root, out string? field))
            {
                path = $"{shapePath}.{field}{suffix}";
            }
        }

        return new InputException(path, MessageWithoutParameter(error));
    }

    /// <summary>The exception's message without the " (Parameter 'x')" that <see cref="ArgumentException"/> appends.</summary>
    /// <param name="error">The exception.</param>
    /// <returns>The library's own sentence, on one line.</returns>
    public static string MessageWithoutParameter(ArgumentException error)
    {
        string message = error.Message;
        if (error.ParamName is not null)
        {
            string suffix = $" (Parameter '{error.ParamName}')";
            if (message.EndsWith(suffix, StringComparison.Ordinal))
            {
                message = message[..^suffix.Length];
            }
        }

        return message.ReplaceLineEndings(" ");
    }
}
