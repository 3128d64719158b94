namespace URWPGSim2D.Server.Json;

/// <summary>One step of a path into the input JSON: a property name, or an array index when <see cref="Name"/> is null.</summary>
/// <param name="Name">The property name, or null for an array element.</param>
/// <param name="Index">The array index (0-based) when <see cref="Name"/> is null.</param>
internal readonly record struct JsonPathSegment(string? Name, int Index)
{
    /// <summary>True for an array element, false for a property.</summary>
    public bool IsIndex => Name is null;

    /// <summary>A property step.</summary>
    /// <param name="name">The property name.</param>
    /// <returns>The segment.</returns>
    public static JsonPathSegment Property(string name) => new(name, 0);

    /// <summary>An array-element step.</summary>
    /// <param name="index">The 0-based index.</param>
    /// <returns>The segment.</returns>
    public static JsonPathSegment Element(int index) => new(null, index);
}
