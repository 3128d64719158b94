namespace URWPGSim2D.Collision.Tests.Queries;

/// <summary>
/// <see cref="ShapeQuery.RayCast(in Shape, Vector2, Vector2)"/> against the first root, in double,
/// of the reference signed distance of a point moving along the ray (a convex function of the fraction).
/// </summary>
public sealed class RayCastQueryTests
{
    private const double Tolerance = Tolerances.Depth;

    public static TheoryData<ShapeKind> Kinds => [.. Enum.GetValues<ShapeKind>()];

    [Theory]
    [MemberData(nameof(Kinds))]
    public void EntryMatchesTheReferenceFirstRoot(ShapeKind kind)
    {
        var rng = new Random(500 + (int)kind);
        var log = new FailureLog();
        int hits = 0;
        foreach (var c in PairCorpus.For(kind, kind).Take(700))
        {
            var shape = c.A;
            var (from, to) = RandomRay(rng, shape.Reference);
            if (kind == ShapeKind.Segment)
            {
                CheckSegment(shape.Shape.AsSegment(), from, to, log, ref hits);
                continue;
            }

            Func<double, double> f = t => shape.Reference.SignedDistance(QueryReference.At(from, to, t));
            double length = Vector2.Distance(from, to);
            if (Math.Abs(f(0)) <= Tolerance || Math.Abs(f(1)) <= Tolerance || NearGrazing(f, length))
            {
                continue; // starts or ends on the boundary, or grazes it: either answer is right
            }

            double? root = QueryReference.FirstRoot(f);
            bool startsInside = f(0) < 0;
            var r = ShapeQuery.RayCast(shape.Shape, from, to);
            log.Case();
            bool expected = root is not null && !startsInside;
            log.Check(r.Hit == expected, $"{shape}: ray {from}→{to}: hit {r.Hit}, reference {(startsInside ? "starts inside" : root?.ToString("R") ?? "miss")}");
            if (!r.Hit || !expected)
            {
                continue;
            }

            hits++;
            Point2 p = Point2.From(r.Point), n = Point2.From(r.Normal);

            // The entry may shift along the ray only by rounding of the boundary across it (its
            // normal component), which grows as the ray meets the edge more obliquely.
            double across = Math.Abs(Point2.Dot(n, (Point2.From(to) - Point2.From(from)) / length));
            log.Check(Math.Abs(r.Fraction - root!.Value) * length * across <= Tolerance, $"{shape}: ray {from}→{to}: fraction {r.Fraction}, reference {root:R}");
            log.Check(Math.Abs(shape.Reference.SignedDistance(p)) <= Tolerance, $"{shape}: ray {from}→{to}: the entry {p} is not on the boundary");
            log.Check(Math.Abs(n.Length - 1) <= Tolerances.UnitLength, $"{shape}: normal {n} is not a unit vector");

            // An outward normal at a boundary point: one mm along it is exactly one mm outside.
            log.Check(Math.Abs(shape.Reference.SignedDistance(p + n) - 1) <= Tolerance, $"{shape}: normal {n} at {p} is not outward ({shape.Reference.SignedDistance(p + n):R})");
        }

        log.AssertNone(300);
        Assert.True(hits > 50, $"only {hits} hits");
    }

    [Fact]
    public void FishEntryIsTheFirstLeafEntered()
    {
        var rng = new Random(77);
        var log = new FailureLog();
        int hits = 0;
        for (int i = 0; i < 400; i++)
        {
            var fish = new FishModel(FishTestKit.Size(rng), FishTestKit.Pose(rng, spread: 50f));
            var leaves = QueryReference.Leaves(fish);
            var (from, to) = RandomRay(rng, leaves[1]);
            double length = Vector2.Distance(from, to);
            var roots = leaves.Select(l =>
            {
                Func<double, double> f = t => l.SignedDistance(QueryReference.At(from, to, t));
                return (Leaf: l, F: f, Root: f(0) < 0 ? null : QueryReference.FirstRoot(f));
            }).ToArray();
            if (roots.Any(x => Math.Abs(x.F(0)) <= Tolerance || NearGrazing(x.F, length)))
            {
                continue;
            }

            log.Case();
            double? first = roots.Where(x => x.Root is not null).Select(x => x.Root).DefaultIfEmpty(null).Min();
            var r = ShapeQuery.RayCast(fish, from, to);
            log.Check(r.Hit == (first is not null), $"{i}: hit {r.Hit}, reference {first}");
            if (r.Hit && first is not null)
            {
                hits++;
                log.Check(Math.Abs(r.Fraction - first.Value) * length <= Tolerance, $"{i}: fraction {r.Fraction}, reference {first:R}");
                log.Check(Math.Abs(leaves[(int)r.Part!.Value].SignedDistance(Point2.From(r.Point))) <= Tolerance, $"{i}: the point is not on the reported leaf {r.Part}");
            }
        }

        log.AssertNone(200);
        Assert.True(hits > 50, $"only {hits} hits");
    }

    [Fact]
    public void CircleEntryIsTheClosedForm()
    {
        var rng = new Random(5);
        for (int i = 0; i < 2000; i++)
        {
            var circle = new Circle(FishTestKit.Point(rng, 1000f), FishTestKit.Range(rng, 5f, 200f));
            Vector2 from = circle.Center + FishTestKit.Point(rng, 600f);
            Vector2 to = circle.Center + FishTestKit.Point(rng, 600f);
            Point2 s = Point2.From(from) - Point2.From(circle.Center), d = Point2.From(to) - Point2.From(from);
            double a = Point2.Dot(d, d), b = Point2.Dot(s, d), cc = Point2.Dot(s, s) - ((double)circle.Radius * circle.Radius);
            double disc = (b * b) - (a * cc);
            double t = disc >= 0 ? (-b - Math.Sqrt(disc)) / a : double.NaN;
            bool expected = cc > 0 && disc >= 0 && t >= 0 && t <= 1;
            var r = ShapeQuery.RayCast(circle, from, to);
            if (Math.Abs(cc) < 1 || Math.Abs(disc) < 1e-3 * a * a || Math.Abs(t) * Math.Sqrt(a) < 1e-2 || Math.Abs(t - 1) * Math.Sqrt(a) < 1e-2)
            {
                continue;
            }

            Assert.True(r.Hit == expected, $"{i}: hit {r.Hit} vs {expected}");
            if (expected)
            {
                Assert.True(Math.Abs(r.Fraction - t) * Math.Sqrt(a) <= 1e-2, $"{i}: {r.Fraction} vs {t}");
            }
        }
    }

    [Fact]
    public void BadRayIsAnArgumentError()
    {
        Shape c = new Circle(Vector2.Zero, 1f);
        var e = Assert.Throws<ArgumentException>(() => ShapeQuery.RayCast(c, new Vector2(float.NaN, 0f), Vector2.One));
        Assert.Equal("from", e.ParamName);
        Assert.False(ShapeQuery.RayCast(c, new Vector2(5f, 0f), new Vector2(5f, 0f)).Hit);
    }

    // A segment has no inside: the truth is the crossing of the two lines, in double.
    private static void CheckSegment(Segment segment, Vector2 from, Vector2 to, FailureLog log, ref int hits)
    {
        Point2 f = Point2.From(from), d = Point2.From(to) - f, a = Point2.From(segment.A), e = Point2.From(segment.B) - a;
        double den = Point2.Cross(d, e);
        double t = Point2.Cross(a - f, e) / den, u = Point2.Cross(a - f, d) / den;
        double margin = 1e-4;
        if (Math.Abs(den) < 1e-3 * d.Length * e.Length || Math.Abs(t) < margin || Math.Abs(t - 1) < margin || Math.Abs(u) < margin || Math.Abs(u - 1) < margin)
        {
            return; // near parallel, or through an end of either: either answer is right
        }

        bool expected = t > 0 && t < 1 && u > 0 && u < 1;
        var r = ShapeQuery.RayCast(segment, from, to);
        log.Case();
        log.Check(r.Hit == expected, $"{segment.A}–{segment.B}: ray {from}→{to}: hit {r.Hit}, reference t {t:R} u {u:R}");
        if (r.Hit && expected)
        {
            hits++;
            log.Check(Math.Abs(r.Fraction - t) * d.Length <= Tolerance, $"ray {from}→{to}: fraction {r.Fraction}, reference {t:R}");
            log.Check(Point2.Dot(Point2.From(r.Normal), d) < 0 && Math.Abs(Point2.Dot(Point2.From(r.Normal), e)) <= 1e-5 * e.Length, $"normal {r.Normal} is not the segment's, facing the ray");
        }
    }

    internal static (Vector2 From, Vector2 To) RandomRay(Random rng, ReferenceShape shape)
    {
        Point2 c = shape.Centre;
        double reach = shape.BoundingRadius * 2.5;
        Point2 from = c + (Point2.FromAngle(rng.NextDouble() * 2 * Math.PI) * (reach * rng.NextDouble()));
        Point2 aim = c + (Point2.FromAngle(rng.NextDouble() * 2 * Math.PI) * (shape.BoundingRadius * 1.2 * rng.NextDouble()));
        Point2 to = from + ((aim - from) * (0.5 + (1.5 * rng.NextDouble())));
        return (from.ToVector2(), to.ToVector2());
    }

    // The ray's closest approach comes within the tolerance of the boundary without clearly entering.
    private static bool NearGrazing(Func<double, double> f, double length)
    {
        double lo = 0, hi = 1;
        for (int i = 0; i < 100; i++)
        {
            double m1 = lo + ((hi - lo) / 3), m2 = hi - ((hi - lo) / 3);
            if (f(m1) <= f(m2))
            {
                hi = m2;
            }
            else
            {
                lo = m1;
            }
        }

        return Math.Abs(f((lo + hi) / 2)) <= 2 * Tolerance + (1e-6 * length);
    }
}
