using System.Runtime.InteropServices;

namespace URWPGSim2D.Collision.Shapes;

/// <summary>
/// A disc in the X–Z plane: every point within <see cref="Radius"/> mm of <see cref="Center"/>
/// (the URWPGSim2D paper calls it a "sphere"). Also serves as the outer bounding circle of
/// every other shape.
/// </summary>
[StructLayout(LayoutKind.Sequential)] // Center's x and z, then Radius: three floats in a row (see Floats)
public readonly struct Circle
{
    /// <summary>Creates a circle, validating its numbers.</summary>
    /// <param name="center">Centre in mm (X = world X, Y = world Z); must be finite.</param>
    /// <param name="radius">Radius in mm; must be finite and &gt; 0.</param>
    /// <exception cref="System.ArgumentException">A coordinate is not finite or the radius is not &gt; 0.</exception>
    public Circle(Vector2 center, float radius)
    {
        Guard.Finite(center, nameof(center));
        Guard.Positive(radius, nameof(radius));
        Center = center;
        Radius = radius;
    }

    private Circle(Vector2 center, float radius, bool unchecked_)
    {
        _ = unchecked_;
        Center = center;
        Radius = radius;
    }

    /// <summary>Centre in mm (X = world X, Y = world Z).</summary>
    public Vector2 Center { get; }

    /// <summary>Radius in mm.</summary>
    public float Radius { get; }

    /// <summary>The outer bounding circle: the circle itself.</summary>
    public Circle BoundingCircle => this;

    /// <summary>True when the two discs' interiors overlap: |c₁ − c₂| &lt; r₁ + r₂. The cheap outer test.</summary>
    /// <param name="other">The other circle.</param>
    /// <returns>Whether they overlap.</returns>
    public bool Overlaps(in Circle other)
    {
        float r = Radius + other.Radius;
        return Vector2.DistanceSquared(Center, other.Center) < r * r;
    }

    /// <summary>This circle moved by <paramref name="offset"/> mm.</summary>
    /// <param name="offset">Translation in mm.</param>
    /// <returns>The translated circle.</returns>
    public Circle Translated(Vector2 offset) => new(Center + offset, Radius, true);

    /// <summary>
    /// The circle's three floats in place: the centre's x, its z, then the radius (the struct's
    /// sequential layout), so that a vector kernel broadcasts each straight from memory.
    /// </summary>
    /// <param name="circle">The circle, read in place.</param>
    /// <returns>A reference to the centre's x; the z and the radius follow it.</returns>
    internal static ref float Floats(in Circle circle) => ref Unsafe.As<Circle, float>(ref Unsafe.AsRef(in circle));

    /// <summary>A bounding circle built by the library; a radius of 0 (a point) is allowed here.</summary>
    internal static Circle Bounding(Vector2 center, float radius) => new(center, radius, true);
}
