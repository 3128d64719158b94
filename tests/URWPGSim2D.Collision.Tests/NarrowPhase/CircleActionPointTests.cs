extern alias baseline;

using System.Numerics;
using URWPGSim2D.Collision.Geometry;
using URWPGSim2D.Collision.Shapes;
using Frozen = baseline::URWPGSim2D.Collision;
using URWPGSim2D.Collision.Tests.Support;
using URWPGSim2D.Testing;
using Xunit.Abstractions;
using Xunit.Sdk;

namespace URWPGSim2D.Collision.Tests.NarrowPhase;

/// <summary>
/// The circle–polygon contact against independent truth: cases worked by hand, a double-precision
/// reference (the contact by exhaustive search, the chord of the polygon on the line through the
/// centre along the normal clipped face by face in double; the action point is the middle of its
/// overlap with the circle), and the frozen kernel of before issue 10: every bit of the contact
/// (intersection, MTV, normal) the same, the action point — whose chord is now taken from the
/// contact feature and the far side (<c>NarrowPhase/CircleChord</c>) — moved by rounding only;
/// on every path: the packed lanes of a polygon, the lanes of a view, the loops.
/// </summary>
public sealed class CircleActionPointTests
{
    private static readonly ShapeKind[] PolygonLike = [ShapeKind.Polygon, ShapeKind.Aabb, ShapeKind.KDop8];

    // Polygons and boxes, whose edge normals are their edges' (an 8-DOP keeps its four fixed axes
    // while its float vertices, rounded from the slabs, can make a short edge's direction differ
    // from its axis by a thousandth of a radian: its truth is the frozen comparison below).
    private static readonly ShapeKind[] EdgeNormalled = [ShapeKind.Polygon, ShapeKind.Aabb];

    private readonly ITestOutputHelper _output;

    public CircleActionPointTests(ITestOutputHelper output) => _output = output;

    public static TheoryData<float, float, float, float, float, float, float, float> HandWorked => new()
    {
        // centre x, z, radius; square half-size; expected mtv x, z, action point x, z.
        // Edge region: the top face at z = 10, centre 5 above it: depth 5, chord [−25, −5] ∩ [−10, 10].
        { 0f, 15f, 10f, 10f, 0f, 5f, 0f, 7.5f },
        // Vertex region of (10, 10): d = (3, 4), |d| = 5, depth 1; the chord meets the corner at t = −5.
        { 13f, 14f, 6f, 10f, 0.6f, 0.8f, 9.7f, 9.6f },
        // Centre inside, 3 below the top face: depth 2 + 3, the circle's own [−2, 2] is the overlap.
        { 0f, 7f, 2f, 10f, 0f, 5f, 0f, 7f },
        // A circle holding the whole square: out through the top face, the chord is the square's [−15, 5].
        { 0f, 5f, 100f, 10f, 0f, 105f, 0f, 0f },
        // Edge region on the left: centre 2 beyond x = −10, depth 4; chord [−22, −2] ∩ [−6, 6].
        { -12f, 3f, 6f, 10f, -4f, 0f, -8f, 3f },
    };

    [Theory]
    [MemberData(nameof(HandWorked))]
    public void HandWorkedContactsOfASquare(float cx, float cz, float r, float half, float mtvX, float mtvZ, float apX, float apZ)
    {
        var circle = new Circle(new Vector2(cx, cz), r);
        var square = new ConvexPolygon([new(-half, -half), new(half, -half), new(half, half), new(-half, half)]);
        var box = new Aabb(new Vector2(-half, -half), new Vector2(half, half));
        foreach (var result in AllPaths(circle, square).Append(CollisionDetector.Detect(circle, box)))
        {
            Assert.True(result.Intersect);
            Assert.Equal(mtvX, result.MinimumTranslationVector.X, 5);
            Assert.Equal(mtvZ, result.MinimumTranslationVector.Z, 5);
            Assert.Equal(apX, result.ActionPoint.X, 5);
            Assert.Equal(apZ, result.ActionPoint.Z, 5);
        }
    }

    [Fact]
    public void AThinPolygonsFarSideCutsTheChord()
    {
        // A 20 × 2 slab under a circle of radius 5 centred 1 above it: the line x = 0 crosses the
        // slab from t = −3 to t = −1, all inside the circle's [−5, 5]; the middle is z = 1.
        var slab = new ConvexPolygon([new(-10f, 0f), new(10f, 0f), new(10f, 2f), new(-10f, 2f)]);
        foreach (var result in AllPaths(new Circle(new Vector2(0f, 3f), 5f), slab))
        {
            Assert.Equal(new Vector3(0f, 0f, 4f), result.MinimumTranslationVector);
            Assert.Equal(0f, result.ActionPoint.X, 5);
            Assert.Equal(1f, result.ActionPoint.Z, 5);
        }

        var narrow = new ConvexPolygon([new(-1f, 0f), new(1f, 0f), new(0f, 3f)]);
        foreach (var result in AllPaths(new Circle(new Vector2(0f, -2f), 6f), narrow))
        {
            // Out through the base (centre 2 below it): normal (0, −1), depth 4; along the normal
            // the triangle spans t from −5 (apex) to −2 (base); the circle holds all of it.
            Assert.Equal(0f, result.MinimumTranslationVector.X, 5);
            Assert.Equal(-4f, result.MinimumTranslationVector.Z, 5);
            Assert.Equal(0f, result.ActionPoint.X, 5);
            Assert.Equal(1.5f, result.ActionPoint.Z, 5);
        }
    }

    [Fact]
    public void AgreesWithADoublePrecisionReference()
    {
        const int seed = 1020;
        var gen = new RandomShapes(seed);
        double worstPoint = 0, worstDepth = 0, worstNormal = 0, largestPointError = 0;
        int compared = 0, farSide = 0;
        for (int trial = 0; trial < 30000; trial++)
        {
            var (a, b, _) = gen.Pair(ShapeKind.Circle, EdgeNormalled[trial % 2]);
            try
            {
                var circle = a.Shape.AsCircle();
                var (vertices, _) = Outline(b.Shape);
                var core = vertices.Select(Point2.From).ToArray();
                var reference = Reference(circle, core);
                var result = CollisionDetector.Detect(a.Shape, b.Shape);
                if (Math.Abs(reference.Depth) <= Tolerances.TouchingBand)
                {
                    continue;
                }

                Assert.Equal(reference.Depth > 0, result.Intersect);
                if (!result.Intersect)
                {
                    continue;
                }

                double allowed = Allowed(Scale(circle, core), circle.Radius);
                double depthError = Math.Abs(result.Depth - reference.Depth);
                worstDepth = Math.Max(worstDepth, depthError / allowed);
                Assert.True(depthError <= allowed, $"depth {result.Depth:R}, reference {reference.Depth:R}");
                if (!reference.WellConditioned)
                {
                    continue;
                }

                compared++;
                farSide += reference.FarSide ? 1 : 0;
                double normalError = Point2.Distance(Point2.FromWorld(result.NormalAxis), reference.Normal);
                worstNormal = Math.Max(worstNormal, normalError / 1e-4);
                Assert.True(normalError <= 1e-4, $"normal {result.NormalAxis}, reference {reference.Normal}");
                double pointError = Point2.Distance(Point2.FromWorld(result.ActionPoint), reference.ActionPoint);
                largestPointError = Math.Max(largestPointError, pointError);
                worstPoint = Math.Max(worstPoint, pointError * reference.Conditioning / allowed);
                Assert.True(pointError * reference.Conditioning <= allowed, $"action point {result.ActionPoint}, reference {reference.ActionPoint} ({pointError:R} mm off, conditioning {reference.Conditioning:R})");
            }
            catch (XunitException e)
            {
                throw RandomCaseException.At(seed, trial, new XunitException($"{a} vs {b}: {e.Message}"));
            }
        }

        _output.WriteLine($"{compared} contacts compared ({farSide} with the polygon's far side inside the circle); worst errors as fractions of the allowance: depth {worstDepth:F3}, normal {worstNormal:F3}, action point {worstPoint:F3} (largest {largestPointError:G3} mm)");
        Assert.InRange(compared, 8000, 30000);

        // Both ends of CircleChord are exercised: contacts whose chord the far side cuts, and the rest.
        Assert.InRange(farSide, 1000, compared - 1000);
    }

    [Fact]
    public void ContactsAreTheFrozenKernelsBitForBitAndActionPointsMoveByRoundingOnly()
    {
        const int seed = 1021;
        var gen = new RandomShapes(seed);
        int hits = 0, moved = 0;
        double worstMove = 0;
        for (int trial = 0; trial < 120000; trial++)
        {
            var (a, b, _) = gen.Pair(ShapeKind.Circle, PolygonLike[trial % 3]);
            try
            {
                var circle = a.Shape.AsCircle();
                var (v, n) = Outline(b.Shape);
                var frozen = Frozen.NarrowPhase.CircleConvex.Detect(new Frozen.Shapes.Circle(circle.Center, circle.Radius), new Frozen.Geometry.ConvexView(v, n));
                var result = CollisionDetector.Detect(a.Shape, b.Shape);
                Assert.Equal(frozen.Intersect, result.Intersect);
                Assert.Equal(Bits(frozen.MinimumTranslationVector), Bits(result.MinimumTranslationVector));
                Assert.Equal(Bits(frozen.NormalAxis), Bits(result.NormalAxis));
                double move = Vector3.Distance(frozen.ActionPoint, result.ActionPoint);
                double allowed = Allowed(Scale(circle, v.Select(Point2.From).ToArray()), circle.Radius);
                moved += move > 0 ? 1 : 0;
                hits += result.Intersect ? 1 : 0;
                if (b.Shape.Kind != ShapeKind.KDop8)
                {
                    worstMove = Math.Max(worstMove, move / allowed);
                    Assert.True(move <= allowed, $"action point {result.ActionPoint}, frozen {frozen.ActionPoint} ({move:R} mm apart)");
                }
                else if (result.Intersect)
                {
                    AssertInBoth(result.ActionPoint, circle, v, n, allowed);
                }
            }
            catch (XunitException e)
            {
                throw RandomCaseException.At(seed, trial, new XunitException($"{a} vs {b}: {e.Message}"));
            }
        }

        _output.WriteLine($"{hits} contacts; {moved} action points moved, the farthest (polygons, boxes) by {worstMove:F3} of the allowance");
        Assert.InRange(hits, 40000, 110000);
    }

    // The point lies in the circle and in the polygon (vertices v, outward face normals n), within `allowed`.
    private static void AssertInBoth(Vector3 point, in Circle circle, Vector2[] v, Vector2[] n, double allowed)
    {
        Point2 p = Point2.FromWorld(point);
        double fromCentre = Point2.Distance(p, Point2.From(circle.Center));
        Assert.True(fromCentre <= circle.Radius + allowed, $"action point {point} is {fromCentre - circle.Radius:G3} mm outside the circle");
        for (int i = 0; i < v.Length; i++)
        {
            double outside = Point2.Dot(Point2.From(n[i]), p - Point2.From(v[i]));
            Assert.True(outside <= allowed, $"action point {point} is {outside:G3} mm outside face {i}");
        }
    }

    // How far a result may be from the truth: 0.001 mm, plus a few float steps at the
    // coordinates' magnitude (a float near 25,000 mm is 0.002 mm from the next), plus 1e-6 of the
    // circle's and polygon's size (float round-off in the arithmetic relative to the polygon).
    private static double Allowed(double coordinates, double size) => 1e-3 + (4.8e-7 * coordinates) + (1e-6 * size);

    private static double Scale(in Circle circle, IReadOnlyList<Point2> core) =>
        Math.Max(Math.Max(Math.Abs(circle.Center.X), Math.Abs(circle.Center.Y)), core.Max(p => Math.Max(Math.Abs(p.X), Math.Abs(p.Y))));

    // The circle–polygon contact in double precision, by exhaustive search: the nearest point of
    // the polygon (centre outside) or the nearest edge line (inside), then the polygon's chord on
    // the line through the centre along the normal, clipped face by face.
    private static (double Depth, Point2 Normal, Point2 ActionPoint, double Conditioning, bool WellConditioned, bool FarSide) Reference(in Circle circle, Point2[] core)
    {
        Point2 c = Point2.From(circle.Center);
        double r = circle.Radius;
        int count = core.Length;
        var separations = Enumerable.Range(0, count).Select(i => ReferenceGeometry.EdgeSeparation(core, i, c)).ToArray();
        Point2 normal;
        double depth;
        bool wellConditioned;
        if (separations.All(s => s <= 0))
        {
            var order = Enumerable.Range(0, count).OrderByDescending(i => separations[i]).ToArray();
            int face = order[0];
            normal = (core[(face + 1) % count] - core[face]).RightPerp.Normalized();
            depth = r - separations[face];
            wellConditioned = separations[face] - separations[order[1]] > 1e-3;
        }
        else
        {
            Point2 nearest = ReferenceGeometry.ClosestOnCore(core, c, out _);
            double gap = Point2.Distance(c, nearest);
            normal = (c - nearest) / gap;
            depth = r - gap;
            wellConditioned = gap > 1e-3;
        }

        var faces = Enumerable.Range(0, count).Select(i => (core[(i + 1) % count] - core[i]).RightPerp.Normalized()).ToArray();
        var (lo, hi, conditioning) = Chord(core, faces, c, normal, r);
        return (depth, normal, c + (normal * (0.5 * (lo + hi))), conditioning, wellConditioned && lo <= hi, lo > -r);
    }

    // The chord [lo, hi] ∩ [−r, r] of the polygon (vertices `core`, outward unit face normals
    // `faces`) on the line c + t·n, clipped face by face in double, and how well its ends are
    // conditioned: the least |nⱼ·n| over the faces whose bound lies near an end (1 where the
    // circle's own ±r ends it). A face nearly parallel to the line moves the end it makes by a
    // rounding divided by that cosine.
    private static (double Lo, double Hi, double Conditioning) Chord(Point2[] core, Point2[] faces, Point2 c, Point2 n, double r)
    {
        int count = core.Length;
        var bounds = new double[count];
        var cosines = new double[count];
        double lo = double.NegativeInfinity, hi = double.PositiveInfinity;
        for (int i = 0; i < count; i++)
        {
            double s = Point2.Dot(faces[i], c - core[i]);
            cosines[i] = Point2.Dot(faces[i], n);
            bounds[i] = cosines[i] == 0 ? double.NaN : -s / cosines[i];
            if (cosines[i] > 0)
            {
                hi = Math.Min(hi, bounds[i]);
            }
            else if (cosines[i] < 0)
            {
                lo = Math.Max(lo, bounds[i]);
            }
        }

        double conditioning = 1;
        const double near = 0.05;
        for (int i = 0; i < count; i++)
        {
            bool endsIt = (lo > -r && Math.Abs(bounds[i] - lo) <= near) || (hi < r && Math.Abs(bounds[i] - hi) <= near);
            if (endsIt)
            {
                conditioning = Math.Min(conditioning, Math.Abs(cosines[i]));
            }
        }

        return (Math.Max(lo, -r), Math.Min(hi, r), Math.Max(conditioning, 1e-3));
    }

    // The circle against a polygon through every path: the packed lanes (CollisionDetector), the
    // lanes of a view, the vector loops and the scalar loops.
    private static CollisionDetectionResult[] AllPaths(Circle circle, ConvexPolygon polygon) =>
    [
        CollisionDetector.Detect(circle, polygon),
        CircleConvex.Detect(circle, polygon.View()),
        CircleConvex.Detect(circle, polygon.View(), vector: true),
        CircleConvex.Detect(circle, polygon.View(), vector: false),
        CollisionDetector.Detect(polygon, circle).Swapped(),
    ];

    private static (Vector2[] Vertices, Vector2[] Normals) Outline(Shape shape)
    {
        switch (shape.Kind)
        {
            case ShapeKind.Polygon:
                return (shape.AsPolygon().Vertices.ToArray(), shape.AsPolygon().Normals.ToArray());
            case ShapeKind.KDop8:
                var view = shape.AsKDop8().View();
                return (view.Vertices.ToArray(), view.Normals.ToArray());
            default:
                var corners = new Vector2[4];
                shape.AsAabb().WriteVertices(corners);
                var box = Aabb.View(corners);
                return (corners, box.Normals.ToArray());
        }
    }

    private static (int, int, int) Bits(Vector3 v) =>
        (BitConverter.SingleToInt32Bits(v.X), BitConverter.SingleToInt32Bits(v.Y), BitConverter.SingleToInt32Bits(v.Z));
}
