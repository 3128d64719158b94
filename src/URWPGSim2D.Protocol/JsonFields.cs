namespace URWPGSim2D.Protocol;

/// <summary>Reads typed values from a <see cref="Utf8JsonReader"/> positioned on a property name, with one-line errors naming the field.</summary>
internal static class JsonFields
{
    /// <summary>Moves to the object's first token; the line must be one JSON object.</summary>
    public static void StartObject(ref Utf8JsonReader r)
    {
        if (!r.Read() || r.TokenType != JsonTokenType.StartObject)
        {
            throw new ProtocolException("a message must be one JSON object");
        }
    }

    /// <summary>Moves to the next property name of the current object; false at its end.</summary>
    public static bool NextProperty(ref Utf8JsonReader r)
    {
        if (!r.Read())
        {
            throw new ProtocolException("the JSON object is not closed");
        }

        return r.TokenType == JsonTokenType.PropertyName;
    }

    /// <summary>Skips the value of the current property (an unknown field).</summary>
    public static void Skip(ref Utf8JsonReader r)
    {
        r.Read();
        r.Skip();
    }

    /// <summary>The value of the current property as an int.</summary>
    public static int Int(ref Utf8JsonReader r, string field)
    {
        r.Read();
        return IntValue(ref r, field);
    }

    /// <summary>The current token as an int.</summary>
    public static int IntValue(ref Utf8JsonReader r, string field)
    {
        if (r.TokenType != JsonTokenType.Number || !r.TryGetInt32(out int value))
        {
            throw new ProtocolException($"{field}: expected an integer, got {Describe(ref r)}");
        }

        return value;
    }

    /// <summary>The value of the current property as a float (<c>null</c> reads as NaN).</summary>
    public static float Float(ref Utf8JsonReader r, string field)
    {
        r.Read();
        return FloatValue(ref r, field);
    }

    /// <summary>The current token as a float (<c>null</c> reads as NaN).</summary>
    public static float FloatValue(ref Utf8JsonReader r, string field)
    {
        if (r.TokenType == JsonTokenType.Null)
        {
            return float.NaN;
        }

        if (r.TokenType != JsonTokenType.Number || !r.TryGetSingle(out float value))
        {
            throw new ProtocolException($"{field}: expected a number, got {Describe(ref r)}");
        }

        return value;
    }

    /// <summary>The value of the current property as a bool.</summary>
    public static bool Bool(ref Utf8JsonReader r, string field)
    {
        r.Read();
        return r.TokenType switch
        {
            JsonTokenType.True => true,
            JsonTokenType.False => false,
            _ => throw new ProtocolException($"{field}: expected true or false, got {Describe(ref r)}"),
        };
    }

    /// <summary>The value of the current property as a string (cut to <see cref="ProtocolLimits.TextChars"/>), or null for <c>null</c>.</summary>
    public static string? Text(ref Utf8JsonReader r, string field) => Text(ref r, field, ProtocolLimits.TextChars);

    /// <summary>The value of the current property as a string cut to <paramref name="maxChars"/>, or null for <c>null</c>.</summary>
    public static string? Text(ref Utf8JsonReader r, string field, int maxChars)
    {
        r.Read();
        if (r.TokenType == JsonTokenType.Null)
        {
            return null;
        }

        if (r.TokenType != JsonTokenType.String)
        {
            throw new ProtocolException($"{field}: expected a string, got {Describe(ref r)}");
        }

        string s = r.GetString()!;
        return s.Length <= maxChars ? s : s[..maxChars];
    }

    /// <summary>Moves into an array value of the current property.</summary>
    public static void StartArray(ref Utf8JsonReader r, string field)
    {
        r.Read();
        if (r.TokenType != JsonTokenType.StartArray)
        {
            throw new ProtocolException($"{field}: expected an array, got {Describe(ref r)}");
        }
    }

    /// <summary>Moves into an object value of the current property.</summary>
    public static void StartObjectValue(ref Utf8JsonReader r, string field)
    {
        r.Read();
        if (r.TokenType != JsonTokenType.StartObject)
        {
            throw new ProtocolException($"{field}: expected an object, got {Describe(ref r)}");
        }
    }

    /// <summary>Moves to the next element of the current array; false at its end.</summary>
    public static bool NextElement(ref Utf8JsonReader r, string field)
    {
        if (!r.Read())
        {
            throw new ProtocolException($"{field}: the array is not closed");
        }

        return r.TokenType != JsonTokenType.EndArray;
    }

    /// <summary>
    /// Moves to the next element of the current array, element <paramref name="n"/>, which must be an object; false at
    /// the array's end. An element beyond <paramref name="capacity"/> (the assignment's count) throws.
    /// </summary>
    public static bool NextObject(ref Utf8JsonReader r, string field, int n, int capacity = int.MaxValue)
    {
        if (!NextElement(ref r, field))
        {
            return false;
        }

        if (n >= capacity)
        {
            throw new ProtocolException($"{field}: more than the assignment's {capacity}");
        }

        if (r.TokenType != JsonTokenType.StartObject)
        {
            throw new ProtocolException($"{field}[{n}]: expected an object, got {Describe(ref r)}");
        }

        return true;
    }

    /// <summary>An array of exactly <paramref name="values"/>.Length numbers.</summary>
    public static void Floats(ref Utf8JsonReader r, string field, scoped Span<float> values)
    {
        StartArray(ref r, field);
        for (int i = 0; i < values.Length; i++)
        {
            if (!NextElement(ref r, field))
            {
                throw new ProtocolException($"{field}: expected {values.Length} numbers, got {i}");
            }

            values[i] = FloatValue(ref r, field);
        }

        if (NextElement(ref r, field))
        {
            throw new ProtocolException($"{field}: expected {values.Length} numbers, got more");
        }
    }

    /// <summary>An <c>[x, y]</c> array.</summary>
    public static Vector2 Vector(ref Utf8JsonReader r, string field)
    {
        Span<float> v = stackalloc float[2];
        Floats(ref r, field, v);
        return new Vector2(v[0], v[1]);
    }

    /// <summary>A short description of the current token for an error message.</summary>
    public static string Describe(ref Utf8JsonReader r) => r.TokenType switch
    {
        JsonTokenType.String => "a string",
        JsonTokenType.Number => "the number " + System.Text.Encoding.UTF8.GetString(r.ValueSpan.Length > 40 ? r.ValueSpan[..40] : r.ValueSpan),
        JsonTokenType.True or JsonTokenType.False => "a boolean",
        JsonTokenType.Null => "null",
        JsonTokenType.StartArray => "an array",
        JsonTokenType.StartObject => "an object",
        _ => "nothing",
    };
}
