namespace URWPGSim2D.Collision.Tests.Support;

/// <summary>
/// A point or vector of the X–Z plane in double precision (X = world X, Y = world Z, mm), used
/// by the test reference so that it never shares the library's float arithmetic.
/// </summary>
public readonly record struct Point2(double X, double Y)
{
    /// <summary>The zero vector.</summary>
    public static Point2 Zero => default;

    /// <summary>Euclidean length.</summary>
    public double Length => Math.Sqrt(X * X + Y * Y);

    /// <summary>Squared Euclidean length.</summary>
    public double LengthSquared => X * X + Y * Y;

    /// <summary>The outward normal of an edge walked counter-clockwise (x–z coordinates): (Y, −X), not normalised.</summary>
    public Point2 RightPerp => new(Y, -X);

    public static Point2 operator +(Point2 a, Point2 b) => new(a.X + b.X, a.Y + b.Y);

    public static Point2 operator -(Point2 a, Point2 b) => new(a.X - b.X, a.Y - b.Y);

    public static Point2 operator -(Point2 a) => new(-a.X, -a.Y);

    public static Point2 operator *(Point2 a, double s) => new(a.X * s, a.Y * s);

    public static Point2 operator *(double s, Point2 a) => new(a.X * s, a.Y * s);

    public static Point2 operator /(Point2 a, double s) => new(a.X / s, a.Y / s);

    /// <summary>Exact widening of a library vector.</summary>
    public static Point2 From(Vector2 v) => new(v.X, v.Y);

    /// <summary>The plane part (X, Z) of a library world vector.</summary>
    public static Point2 FromWorld(Vector3 v) => new(v.X, v.Z);

    /// <summary>Dot product.</summary>
    public static double Dot(Point2 a, Point2 b) => a.X * b.X + a.Y * b.Y;

    /// <summary>2D cross product a.X·b.Y − a.Y·b.X (positive when b is counter-clockwise of a).</summary>
    public static double Cross(Point2 a, Point2 b) => a.X * b.Y - a.Y * b.X;

    /// <summary>Distance between two points.</summary>
    public static double Distance(Point2 a, Point2 b) => (a - b).Length;

    /// <summary>The unit vector of angle <paramref name="radians"/> from +X toward +Z.</summary>
    public static Point2 FromAngle(double radians) => new(Math.Cos(radians), Math.Sin(radians));

    /// <summary>This vector scaled to length 1 (zero stays zero).</summary>
    public Point2 Normalized()
    {
        double len = Length;
        return len > 0 ? this / len : this;
    }

    /// <summary>Rounds to the library's float vector.</summary>
    public Vector2 ToVector2() => new((float)X, (float)Y);

    /// <inheritdoc />
    public override string ToString() => $"({X:R}, {Y:R})";
}
