namespace URWPGSim2D.Collision.Geometry;

/// <summary>Argument checks shared by every shape constructor: the message names the value.</summary>
internal static class Guard
{
    public static void Finite(float value, string paramName)
    {
        if (!float.IsFinite(value))
        {
            throw new ArgumentException($"must be a finite number, got {value}", paramName);
        }
    }

    public static void Finite(Vector2 value, string paramName)
    {
        if (!float.IsFinite(value.X) || !float.IsFinite(value.Y))
        {
            throw new ArgumentException($"must have finite coordinates, got [{value.X}, {value.Y}]", paramName);
        }
    }

    public static void Positive(float value, string paramName)
    {
        Finite(value, paramName);
        if (!(value > 0f))
        {
            throw new ArgumentException($"must be > 0, got {value}", paramName);
        }
    }
}
