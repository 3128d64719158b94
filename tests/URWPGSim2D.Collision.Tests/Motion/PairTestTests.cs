namespace URWPGSim2D.Collision.Tests.Motion;

/// <summary>
/// A motion world body tested at its current pose without rebuilding (a fish's partner carried into
/// the frame of a model left at an older pose, a polygon's outline posed in place) finds the same
/// contact as the library's plain tests on shapes built at the pose: fish against fish, ball,
/// moving polygon, round and rectangle obstacles, goal blocks, segments, 8-DOPs and walls; polygon
/// against ball, polygon, static shapes and walls — over random poses, joints and model offsets.
/// </summary>
public sealed class PairTestTests
{
    private const int Trials = 1500;

    [Fact]
    public void EveryPairKindMatchesShapesBuiltAtThePose()
    {
        var random = new Random(2024);
        var field = new Field();
        var square = new ConvexPolygon([new Vector2(-40f, -25f), new Vector2(40f, -25f), new Vector2(40f, 25f), new Vector2(-40f, 25f)]);
        Body a = Body.Fish(0, FishSize.Default, new FishPose(Vector2.Zero, 0f));
        Body b = Body.Fish(1, FishSize.Default, new FishPose(new Vector2(300f, 0f), 0f));
        Body ball = Body.Circle(2, 58f, Vector2.Zero);
        Body polygon = Body.Polygon(3, square, Vector2.Zero, 0f);
        Body[] statics =
        [
            Body.Static(4, new Circle(new Vector2(0f, -300f), 58f)),
            Body.Static(5, Rectangle(new Vector2(-300f, 0f), 100f, 60f, 0.4f)),
            Body.Static(6, field.GoalBlocks[0]),
            Body.Static(7, new Segment(new Vector2(200f, 200f), new Vector2(350f, 260f))),
            Body.Static(8, KDop8.FromPoints([new Vector2(-200f, 250f), new Vector2(-120f, 230f), new Vector2(-150f, 330f)])),
            Body.Walls(9, field),
        ];
        int contacts = 0, different = 0;
        int[] seen = new int[16];
        for (int trial = 0; trial < Trials; trial++)
        {
            try
            {
                Place(random, a, Vector2.Zero, 1600f);
                Place(random, b, a.Position, 420f);
                ball.Position = a.Position + RandomVector(random, 330f);
                ball.Invalidate();
                polygon.Position = a.Position + RandomVector(random, 300f);
                polygon.Heading = (float)((random.NextDouble() * 2.0 * Math.PI) - Math.PI);
                polygon.Invalidate();

                // Models at older poses (same joints), as inside a step.
                a.SyncModelAt(a.Position - RandomVector(random, 40f), a.Heading - (((float)random.NextDouble() - 0.5f) * 0.2f));
                b.SyncModelAt(b.Position - RandomVector(random, 40f), b.Heading - (((float)random.NextDouble() - 0.5f) * 0.2f));
                int kind = 0;
                Check(a, b, Exact(a, b), ref contacts, ref different, seen, kind++);
                Check(a, ball, Exact(a, ball), ref contacts, ref different, seen, kind++);
                Check(a, polygon, Exact(a, polygon), ref contacts, ref different, seen, kind++);
                Check(polygon, ball, Exact(polygon, ball), ref contacts, ref different, seen, kind++);
                foreach (Body s in statics)
                {
                    Check(a, s, Exact(a, s), ref contacts, ref different, seen, kind++);
                    Check(polygon, s, Exact(polygon, s), ref contacts, ref different, seen, kind++);
                }
            }
            catch (XunitException e)
            {
                throw RandomCaseException.At(2024, trial, e);
            }
        }

        Assert.True(different <= contacts / 50, $"{different} of {contacts} contacts differ in MTV, action point or parts");
        int kinds = 0;
        foreach (int n in seen)
        {
            kinds += n > 10 ? 1 : 0;
        }

        Assert.True(contacts > 2000 && kinds >= 10, $"{contacts} contacts; by kind {string.Join(",", seen)}");
    }

    private static void Check(Body a, Body b, FishContact exact, ref int contacts, ref int different, int[] seen, int kind)
    {
        Hit found = PairTest.Detect(a, b);
        Hit truth = Hit.From(exact);
        Assert.True(found.Intersect == truth.Intersect || MathF.Max(found.Depth, truth.Depth) < 1e-3f, $"{a.Kind}-{b.Kind} (kind {kind}): {found.Depth} vs {truth.Depth}");
        Assert.True(PairTest.Gap(a, b) <= 0f || !truth.Intersect, $"{a.Kind}-{b.Kind}: the gap bound says apart, yet they overlap by {truth.Depth}");
        if (!found.Intersect || !truth.Intersect)
        {
            return;
        }

        contacts++;
        seen[kind]++;
        Assert.Equal(truth.Depth, found.Depth, 2e-3f);

        // Two leaf pairs can be equally deep (a tie settled by rounding): the same depth is
        // required, the same MTV, action point and parts for nearly every contact.
        bool same = Vector2.Distance(truth.Mtv, found.Mtv) < 5e-3f && Vector2.Distance(truth.Point, found.Point) < 0.05f
            && truth.PartA == found.PartA && truth.PartB == found.PartB;
        different += same ? 0 : 1;
    }

    // The reference: fish rebuilt exactly at their poses, polygons built at theirs, the library's plain tests.
    private static FishContact Exact(Body a, Body b)
    {
        if (a.Kind == BodyKind.Polygon)
        {
            ConvexPolygon p = Posed(a);
            return b.Kind switch
            {
                BodyKind.Circle => new FishContact(CollisionDetector.Detect(p, new Circle(b.Position, b.Radius)), null, null),
                BodyKind.Walls => new FishContact(b.Field!.Contain(p.Vertices), null, null),
                _ => new FishContact(CollisionDetector.Detect((Shape)p, b.Shape), null, null),
            };
        }

        FishModel fish = Rebuilt(a);
        FishContact contact = b.Kind switch
        {
            BodyKind.Fish => FishCollision.Detect(fish, Rebuilt(b)),
            BodyKind.Circle => FishCollision.Detect(fish, new Circle(b.Position, b.Radius)),
            BodyKind.Polygon => FishCollision.Detect(fish, Posed(b)),
            BodyKind.Walls => b.Field!.Contain(fish),
            _ => FishCollision.Detect(fish, b.Shape),
        };
        return contact;
    }

    private static FishModel Rebuilt(Body fish) => new(fish.Model!.Size, new FishPose(fish.Position, fish.Heading, fish.Joint1, fish.Joint2, fish.Joint3));

    private static ConvexPolygon Posed(Body polygon)
    {
        var (sin, cos) = MathF.SinCos(polygon.Heading);
        Span<Vector2> v = stackalloc Vector2[polygon.LocalVertices.Length];
        for (int i = 0; i < v.Length; i++)
        {
            Vector2 p = polygon.LocalVertices[i];
            v[i] = polygon.Position + new Vector2((p.X * cos) - (p.Y * sin), (p.X * sin) + (p.Y * cos));
        }

        return new ConvexPolygon(v);
    }

    private static ConvexPolygon Rectangle(Vector2 center, float length, float width, float heading)
    {
        Vector2 u = new(MathF.Cos(heading), MathF.Sin(heading));
        Vector2 n = new(-u.Y, u.X);
        Vector2 l = u * (length * 0.5f), w = n * (width * 0.5f);
        return new ConvexPolygon([center + l + w, center - l + w, center - l - w, center + l - w]);
    }

    private static void Place(Random random, Body fish, Vector2 around, float spread)
    {
        fish.Position = Vector2.Clamp(around + RandomVector(random, spread), new Vector2(-1350f, -900f), new Vector2(1350f, 900f));
        fish.Heading = (float)((random.NextDouble() * 2.0 * Math.PI) - Math.PI);
        fish.Joint1 = ((float)random.NextDouble() - 0.5f) * 0.6f;
        fish.Joint2 = ((float)random.NextDouble() - 0.5f) * 0.6f;
        fish.Joint3 = ((float)random.NextDouble() - 0.5f) * 0.6f;
        fish.Invalidate();
    }

    private static Vector2 RandomVector(Random random, float size) =>
        new(((float)random.NextDouble() - 0.5f) * 2f * size, ((float)random.NextDouble() - 0.5f) * 2f * size);
}
