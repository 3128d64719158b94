namespace URWPGSim2D.Server.Json;

/// <summary>
/// Reads the fields of one input object with path-aware errors: a field that is absent or null,
/// or an array of the wrong length, becomes a <see cref="InputException"/> naming
/// <c>OBJECT.FIELD</c>. Values themselves (finite, positive, ...) are checked by the library.
/// </summary>
/// <param name="objectPath">The path of the object being read, e.g. <c>pairs[3].a</c>.</param>
internal readonly struct FieldReader(string objectPath)
{
    /// <summary>The message for a required field that is absent or null.</summary>
    public const string MissingMessage = "required field is missing or null";

    /// <summary>The path of the object being read.</summary>
    public string ObjectPath { get; } = objectPath;

    /// <summary>The path of one of the object's fields.</summary>
    /// <param name="field">The JSON field name.</param>
    /// <returns><c>OBJECT.FIELD</c>.</returns>
    public string PathOf(string field) => $"{ObjectPath}.{field}";

    /// <summary>A required string.</summary>
    /// <param name="value">The deserialized value.</param>
    /// <param name="field">The JSON field name.</param>
    /// <returns>The string.</returns>
    public string String(string? value, string field) => value ?? throw Missing(field);

    /// <summary>A required number, mm or rad.</summary>
    /// <param name="value">The deserialized value.</param>
    /// <param name="field">The JSON field name.</param>
    /// <returns>The number (not yet checked for finiteness).</returns>
    public float Number(float? value, string field) => value ?? throw Missing(field);

    /// <summary>A required point <c>[x, z]</c>, as a plane vector (X = x, Y = z), mm.</summary>
    /// <param name="value">The deserialized array.</param>
    /// <param name="field">The JSON field name.</param>
    /// <returns>The point.</returns>
    public Vector2 Point(float[]? value, string field)
    {
        var v = value ?? throw Missing(field);
        return ToPoint(v, PathOf(field));
    }

    /// <summary>A required array of exactly four numbers (8-DOP slab values s0..s3), mm.</summary>
    /// <param name="value">The deserialized array.</param>
    /// <param name="field">The JSON field name.</param>
    /// <returns>The four numbers.</returns>
    public float[] Slabs(float[]? value, string field)
    {
        var v = value ?? throw Missing(field);
        if (v.Length != 4)
        {
            throw new InputException(PathOf(field), $"must be an array of 4 numbers [s0, s1, s2, s3], got {v.Length}");
        }

        return v;
    }

    /// <summary>A required array of exactly <paramref name="count"/> numbers (joint angles in rad, lengths in mm).</summary>
    /// <param name="value">The deserialized array.</param>
    /// <param name="field">The JSON field name.</param>
    /// <param name="count">How many numbers the field holds.</param>
    /// <param name="form">The expected form for the message, e.g. <c>[φ1, φ2, φ3]</c>.</param>
    /// <returns>The numbers (not yet checked for finiteness).</returns>
    public float[] Numbers(float[]? value, string field, int count, string form)
    {
        var v = value ?? throw Missing(field);
        if (v.Length != count)
        {
            throw new InputException(PathOf(field), $"must be an array of {count} numbers {form}, got {v.Length}");
        }

        return v;
    }

    /// <summary>A required array of points <c>[[x, z], ...]</c> (any count; the library checks the count).</summary>
    /// <param name="value">The deserialized array.</param>
    /// <param name="field">The JSON field name.</param>
    /// <returns>The points as plane vectors.</returns>
    public Vector2[] Points(float[]?[]? value, string field)
    {
        var v = value ?? throw Missing(field);
        var points = new Vector2[v.Length];
        for (int i = 0; i < v.Length; i++)
        {
            string path = $"{PathOf(field)}[{i}]";
            points[i] = ToPoint(v[i] ?? throw new InputException(path, "must be an array of 2 numbers [x, z], got null"), path);
        }

        return points;
    }

    /// <summary>The error for a required field that is absent or null.</summary>
    /// <param name="field">The JSON field name.</param>
    /// <returns>The exception to throw.</returns>
    public InputException Missing(string field) => new(PathOf(field), MissingMessage);

    private static Vector2 ToPoint(ReadOnlySpan<float> v, string path) => v.Length == 2
        ? new Vector2(v[0], v[1])
        : throw new InputException(path, $"must be an array of 2 numbers [x, z], got {v.Length}");
}
