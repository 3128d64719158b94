using System.Diagnostics.CodeAnalysis;
using System.Runtime.CompilerServices;

namespace URWPGSim2D.Collision.Shapes;

/// <summary>
/// An axis-aligned box in the X–Z plane: the points with Min.X ≤ x ≤ Max.X and Min.Y ≤ z ≤ Max.Y
/// (vector Y = world Z), in mm. A zero width or height (a flat box) is allowed.
/// </summary>
public readonly struct Aabb
{
    private static readonly Vector2[] EdgeNormals = [new(0f, -1f), new(1f, 0f), new(0f, 1f), new(-1f, 0f)];

    /// <summary>Creates a box from its corners, validating them.</summary>
    /// <param name="min">Lower corner (smallest x and z), mm.</param>
    /// <param name="max">Upper corner (largest x and z), mm.</param>
    /// <exception cref="ArgumentException">A coordinate is not finite, or min exceeds max on an axis.</exception>
    public Aabb(Vector2 min, Vector2 max)
    {
        Guard.Finite(min, nameof(min));
        Guard.Finite(max, nameof(max));
        if (min.X > max.X || min.Y > max.Y)
        {
            Inverted(min, max);
        }

        Min = min;
        Max = max;
    }

    [DoesNotReturn]
    [MethodImpl(MethodImplOptions.NoInlining)]
    private static void Inverted(Vector2 min, Vector2 max) =>
        throw new ArgumentException(
            min.X > max.X ? $"min x ({min.X}) is greater than max x ({max.X})" : $"min z ({min.Y}) is greater than max z ({max.Y})", nameof(min));

    // Trusted corners from the library's own arithmetic (finite, min ≤ max): no checks.
    private Aabb(Vector2 min, Vector2 max, bool trusted)
    {
        _ = trusted;
        Min = min;
        Max = max;
    }

    /// <summary>Lower corner (smallest x, smallest z), mm.</summary>
    public Vector2 Min { get; }

    /// <summary>Upper corner (largest x, largest z), mm.</summary>
    public Vector2 Max { get; }

    /// <summary>The centre of the box, mm.</summary>
    public Vector2 Center => (Min + Max) * 0.5f;

    /// <summary>The outer bounding circle: centred on the box, through its corners.</summary>
    public Circle BoundingCircle => Circle.Bounding(Center, (Max - Min).Length() * 0.5f);

    /// <summary>True when the interiors of the two boxes overlap.</summary>
    /// <param name="other">The other box.</param>
    /// <returns>Whether they overlap.</returns>
    public bool Overlaps(in Aabb other) =>
        Min.X < other.Max.X && other.Min.X < Max.X && Min.Y < other.Max.Y && other.Min.Y < Max.Y;

    /// <summary>This box moved by <paramref name="offset"/> mm.</summary>
    /// <param name="offset">Translation in mm.</param>
    /// <returns>The translated box.</returns>
    public Aabb Translated(Vector2 offset) => new(Min + offset, Max + offset);

    /// <summary>A box from corners the library computed itself (finite, min ≤ max on both axes); not validated.</summary>
    internal static Aabb Trusted(Vector2 min, Vector2 max) => new(min, max, true);

    /// <summary>Writes the four corners counter-clockwise (in x–z coordinates), starting at <see cref="Min"/>.</summary>
    internal void WriteVertices(Span<Vector2> destination)
    {
        destination[0] = Min;
        destination[1] = new Vector2(Max.X, Min.Y);
        destination[2] = Max;
        destination[3] = new Vector2(Min.X, Max.Y);
    }

    /// <summary>A view of the box over the four corners written by <see cref="WriteVertices"/>.</summary>
    internal static ConvexView View(ReadOnlySpan<Vector2> corners) => new(corners, EdgeNormals);
}
