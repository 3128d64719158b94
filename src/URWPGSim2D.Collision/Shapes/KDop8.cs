using System.Diagnostics.CodeAnalysis;

namespace URWPGSim2D.Collision.Shapes;

/// <summary>
/// An 8-DOP (discrete-orientation polytope with 8 faces): the intersection of four slabs
/// minᵢ ≤ p·aᵢ ≤ maxᵢ along the fixed unit axes a₀ = (1, 0), a₁ = (0, 1), a₂ = (√½, √½),
/// a₃ = (√½, −√½) of the X–Z plane (vector Y = world Z), in mm. At most an octagon.
/// </summary>
/// <remarks>
/// On construction the slabs are tightened so that every slab touches the shape (a redundant
/// slab is moved in, rounded outward to float), which makes the projection of the shape on axis
/// i [<see cref="GetMin"/>, <see cref="GetMax"/>]. The polygon is computed in double precision
/// and each vertex rounded to the nearest float; every edge carries the exact normal of its slab.
/// Slabs computed from points (<see cref="FromPoints"/>, <see cref="FromAabb"/>,
/// <see cref="Translated"/>) are rounded outward, so the points stay inside. The vertices are
/// kept inline: no heap. A flat or single-point 8-DOP (min = max on some axis) is allowed.
/// </remarks>
public readonly struct KDop8
{
    /// <summary>√½, the component of the diagonal axes.</summary>
    internal const float Diagonal = 0.70710678118654752f;

    private static readonly Vector2[] SlabAxes = [new(1f, 0f), new(0f, 1f), new(Diagonal, Diagonal), new(Diagonal, -Diagonal)];

    private readonly Vector4 _min;
    private readonly Vector4 _max;
    private readonly VertexBuffer8 _vertices;
    private readonly VertexBuffer8 _normals;
    private readonly int _count;

    /// <summary>Creates an 8-DOP from its slab bounds, validating and tightening them.</summary>
    /// <param name="min">Four lower slab values along a₀..a₃, mm.</param>
    /// <param name="max">Four upper slab values along a₀..a₃, mm.</param>
    /// <exception cref="ArgumentException">Not four values each, a value not finite, min &gt; max on an axis, or slabs with no common point.</exception>
    public KDop8(ReadOnlySpan<float> min, ReadOnlySpan<float> max)
    {
        if (min.Length != 4)
        {
            throw new ArgumentException($"8-DOP needs 4 slab minima, got {min.Length}", nameof(min));
        }

        if (max.Length != 4)
        {
            throw new ArgumentException($"8-DOP needs 4 slab maxima, got {max.Length}", nameof(max));
        }

        for (int i = 0; i < 4; i++)
        {
            Guard.Finite(min[i], $"{nameof(min)}[{i}]");
            Guard.Finite(max[i], $"{nameof(max)}[{i}]");
            if (min[i] > max[i])
            {
                throw new ArgumentException($"min[{i}] ({min[i]}) is greater than max[{i}] ({max[i]})", nameof(min));
            }
        }

        this = Build(new Vector4(min[0], min[1], min[2], min[3]), new Vector4(max[0], max[1], max[2], max[3]));
        if (_count == 0)
        {
            throw new ArgumentException("8-DOP slabs have no point in common (the diagonal slabs miss the box)", nameof(min));
        }
    }

    private KDop8(Vector4 min, Vector4 max, in VertexBuffer8 vertices, in VertexBuffer8 normals, int count)
    {
        _min = min;
        _max = max;
        _vertices = vertices;
        _normals = normals;
        _count = count;
    }

    /// <summary>The unit axis aᵢ (i = 0..3) along which slab i is measured.</summary>
    /// <param name="index">0: (1, 0); 1: (0, 1); 2: (√½, √½); 3: (√½, −√½).</param>
    /// <returns>The axis as a plane vector.</returns>
    public static Vector2 Axis(int index) => SlabAxes[index];

    /// <summary>The tight 8-DOP of a set of points (their projections on the four axes).</summary>
    /// <param name="points">At least one finite point, mm.</param>
    /// <returns>The smallest 8-DOP containing the points.</returns>
    /// <exception cref="ArgumentException">No points, or a coordinate that is not finite.</exception>
    public static KDop8 FromPoints(ReadOnlySpan<Vector2> points)
    {
        if (points.IsEmpty)
        {
            throw new ArgumentException("8-DOP needs at least one point", nameof(points));
        }

        for (int i = 0; i < points.Length; i++)
        {
            Guard.Finite(points[i], $"{nameof(points)}[{i}]");
        }

        Slabs(points, out Vector4 min, out Vector4 max);
        return Build(min, max);
    }

    /// <summary>The 8-DOP equal to a box: its diagonal slabs pass through the box's corners.</summary>
    /// <param name="box">The box.</param>
    /// <returns>The same region as an 8-DOP.</returns>
    public static KDop8 FromAabb(in Aabb box)
    {
        SlabsOf(box, out Vector4 min, out Vector4 max);
        return Build(min, max);
    }

    /// <summary>The lower slab value along axis <paramref name="axis"/> (0..3), mm.</summary>
    /// <param name="axis">Axis index 0..3.</param>
    /// <returns>min over the shape of p·aᵢ.</returns>
    public float GetMin(int axis) => _min[axis];

    /// <summary>The upper slab value along axis <paramref name="axis"/> (0..3), mm.</summary>
    /// <param name="axis">Axis index 0..3.</param>
    /// <returns>max over the shape of p·aᵢ.</returns>
    public float GetMax(int axis) => _max[axis];

    /// <summary>The vertices (1 to 8), counter-clockwise in x–z coordinates, mm.</summary>
    [UnscopedRef]
    public ReadOnlySpan<Vector2> Vertices => ((ReadOnlySpan<Vector2>)_vertices)[.._count];

    /// <summary>The outer bounding circle: centred on the vertex mean, through the farthest vertex.</summary>
    public Circle BoundingCircle
    {
        get
        {
            var v = Vertices;
            Vector2 c = Vector2.Zero;
            foreach (var p in v)
            {
                c += p - v[0];
            }

            c = v[0] + c / v.Length;
            float r2 = 0f;
            foreach (var p in v)
            {
                r2 = MathF.Max(r2, Vector2.DistanceSquared(p, c));
            }

            return Circle.Bounding(c, MathF.Sqrt(r2));
        }
    }

    /// <summary>True when the interiors of the two 8-DOPs overlap (all four slab pairs overlap).</summary>
    /// <param name="other">The other 8-DOP.</param>
    /// <returns>Whether they overlap.</returns>
    public bool Overlaps(in KDop8 other) => SlabsOverlap(_min, _max, other._min, other._max);

    /// <summary>This 8-DOP moved by <paramref name="offset"/> mm.</summary>
    /// <param name="offset">Translation in mm.</param>
    /// <returns>The translated 8-DOP; each slab value is computed in double and rounded outward, so it may grow by one float ulp.</returns>
    public KDop8 Translated(Vector2 offset)
    {
        Guard.Finite(offset, nameof(offset));
        Vector4 min = default, max = default;
        for (int i = 0; i < 4; i++)
        {
            double d = KDop8Vertices.Project(offset.X, offset.Y, i);
            min[i] = KDop8Vertices.RoundDown(_min[i] + d);
            max[i] = KDop8Vertices.RoundUp(_max[i] + d);
        }

        return Build(min, max);
    }

    internal Vector4 MinSlabs => _min;

    internal Vector4 MaxSlabs => _max;

    /// <summary>A view over the inline vertices and their edge normals.</summary>
    [UnscopedRef]
    internal ConvexView View() =>
        new(Vertices, ((ReadOnlySpan<Vector2>)_normals)[..(_count >= 2 ? _count : 0)]);

    /// <summary>p·a₀..a₃ of one point in float (for conservative pre-tests; exact slabs use double).</summary>
    internal static Vector4 Project(Vector2 p) => new(p.X, p.Y, (p.X + p.Y) * Diagonal, (p.X - p.Y) * Diagonal);

    /// <summary>Open-interval overlap on all four axes.</summary>
    internal static bool SlabsOverlap(Vector4 minA, Vector4 maxA, Vector4 minB, Vector4 maxB) =>
        Vector4.LessThanAll(minA, maxB) && Vector4.LessThanAll(minB, maxA);

    /// <summary>
    /// The slab bounds of a point set: p·aᵢ computed in double and rounded outward to float, so
    /// that every point lies inside (the diagonal projections are irrational).
    /// </summary>
    internal static void Slabs(ReadOnlySpan<Vector2> points, out Vector4 min, out Vector4 max)
    {
        // One pass over the points for the four axes (each axis's projections as KDop8Vertices.Project gives them).
        double lo0 = double.PositiveInfinity, lo1 = double.PositiveInfinity, lo2 = double.PositiveInfinity, lo3 = double.PositiveInfinity;
        double hi0 = double.NegativeInfinity, hi1 = double.NegativeInfinity, hi2 = double.NegativeInfinity, hi3 = double.NegativeInfinity;
        foreach (Vector2 p in points)
        {
            double x = p.X, y = p.Y;
            double d2 = KDop8Vertices.Project(x, y, 2), d3 = KDop8Vertices.Project(x, y, 3);
            lo0 = Math.Min(lo0, x);
            hi0 = Math.Max(hi0, x);
            lo1 = Math.Min(lo1, y);
            hi1 = Math.Max(hi1, y);
            lo2 = Math.Min(lo2, d2);
            hi2 = Math.Max(hi2, d2);
            lo3 = Math.Min(lo3, d3);
            hi3 = Math.Max(hi3, d3);
        }

        min = new Vector4(KDop8Vertices.RoundDown(lo0), KDop8Vertices.RoundDown(lo1), KDop8Vertices.RoundDown(lo2), KDop8Vertices.RoundDown(lo3));
        max = new Vector4(KDop8Vertices.RoundUp(hi0), KDop8Vertices.RoundUp(hi1), KDop8Vertices.RoundUp(hi2), KDop8Vertices.RoundUp(hi3));
    }

    /// <summary>The four slabs of a box: x, z, and the diagonals through its corners (rounded outward).</summary>
    internal static void SlabsOf(in Aabb box, out Vector4 min, out Vector4 max)
    {
        Vector2 lo = box.Min, hi = box.Max;
        min = new Vector4(lo.X, lo.Y, KDop8Vertices.RoundDown(KDop8Vertices.Project(lo.X, lo.Y, 2)), KDop8Vertices.RoundDown(KDop8Vertices.Project(lo.X, hi.Y, 3)));
        max = new Vector4(hi.X, hi.Y, KDop8Vertices.RoundUp(KDop8Vertices.Project(hi.X, hi.Y, 2)), KDop8Vertices.RoundUp(KDop8Vertices.Project(hi.X, lo.Y, 3)));
    }

    /// <summary>Builds the tight 8-DOP of the slab intersection; count 0 when it is empty.</summary>
    internal static KDop8 Build(Vector4 min, Vector4 max)
    {
        var vertices = default(VertexBuffer8);
        var normals = default(VertexBuffer8);
        int count = KDop8Vertices.Compute(min, max, vertices, normals, out Vector4 tightMin, out Vector4 tightMax);
        return new KDop8(tightMin, tightMax, vertices, normals, count);
    }
}
