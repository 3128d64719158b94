using URWPGSim2D.Collision;
using Xunit.Sdk;
using static URWPGSim2D.Server.Tests.Cli.ShapeText;

namespace URWPGSim2D.Server.Tests.Cli;

/// <summary>
/// <c>collide</c> with fish: hand-checked contacts on the reference's θ = 0 fish (both orders),
/// part names, the output form, agreement with brute force over the reference's leaf polygons
/// (fish–ball), and with <see cref="FishCollision"/> called directly on random pairs of every
/// kind (the command's dispatch: which side is the fish, swapped pairs, part names).
/// </summary>
public sealed class CollideFishTests
{
    private const double Tolerance = 1e-4;

    public static TheoryData<string, string, double[], string> HandCheckedContacts() => new()
    {
        // Fish at the origin, θ = 0 (worked example). Expected: mtv x, z, normal x, z, action point x, z.
        // A ball above the body (its left side, z = −22.5) at x = 70, past the left fin (which ends
        // at x = 40; its corner (40, −22.5) is 63.5 from the centre): 2 deep. The fish leaves along
        // +z; the overlap on the centre line is z ∈ [−22.5, −20.5].
        { "ball on the body", Circle(70, -78.5, 58), [0, 2, 0, 1, 70, -21.5], "body" },

        // A ball in front of the head tip (110, 0), 3 deep (the tip's vertex region): overlap x ∈ [107, 110].
        { "ball on the head tip", Circle(165, 0, 58), [-3, 0, -1, 0, 108.5, 0], "body" },

        // A ball left of the left caudal tip (−344, −50), 1 deep (the tip's vertex region: both
        // edges leave it toward +x). The line z = −50 through the ball's centre meets the triangle
        // only at its tip, so the action point is the tip itself.
        { "ball on the left caudal tip", Circle(-401, -50, 58), [1, 0, 1, 0, -344, -50], "leftCaudal" },

        // A ball below the right pectoral fin's outer corner (−46.667, 60), 1 deep (vertex region:
        // its edges go up and up-right): overlap z ∈ [59, 60] on x = −46.667.
        { "ball on the right pectoral tip", Circle(-140.0 / 3, 117, 58), [0, -1, 0, -1, -140.0 / 3, 59.5], "rightPectoral" },
    };

    [Theory]
    [MemberData(nameof(HandCheckedContacts))]
    public void AShapeTouchingAKnownLeafOfTheReferenceFish(string what, string shape, double[] expected, string part)
    {
        var (fishFirst, shapeFirst) = (Answer(Pair(Fish(0, 0, 0), shape)), Answer(Pair(shape, Fish(0, 0, 0))));

        AssertResult(fishFirst, expected, what);
        Assert.Equal((part, null), (Part(fishFirst, "partA"), Part(fishFirst, "partB")));

        // Swapped: MTV and normal negated, action point kept, parts exchanged.
        AssertResult(shapeFirst, [-expected[0], -expected[1], -expected[2], -expected[3], expected[4], expected[5]], what + " (swapped)");
        Assert.Equal((null, part), (Part(shapeFirst, "partA"), Part(shapeFirst, "partB")));
    }

    [Fact]
    public void AFishHeadPokingIntoAnotherFishsBodyFromBelow()
    {
        // Fish b points up (θ = −π/2) from (70, 129.5): its head tip is (70, 19.5), 3 inside the
        // lower side z = 22.5 of fish a's body, clear of a's right fin (x ≤ 40) and of b's own fins
        // (z ≥ 89.5). The least push is a moving 3 along −z; the overlap is the small triangle of
        // b's head below z = 22.5 (|x − 70| ≤ 2.25 at z = 22.5).
        string a = Fish(0, 0, 0), b = Fish(70, 129.5, -Math.PI / 2);

        var ab = Answer(Pair(a, b));
        var ba = Answer(Pair(b, a));

        Assert.True(ab.GetProperty("intersect").GetBoolean());
        AssertVector(ab, "mtv", 0, -3);
        AssertVector(ab, "normal", 0, -1);
        var (x, z) = Vector(ab, "actionPoint");
        Assert.InRange(z, 19.5 - Tolerance, 22.5 + Tolerance);
        Assert.InRange(Math.Abs(x - 70), 0, 2.25 * (z - 19.5) / 3 + Tolerance);
        Assert.Equal(("body", "body"), (Part(ab, "partA"), Part(ab, "partB")));

        AssertVector(ba, "mtv", 0, 3);
        AssertVector(ba, "normal", 0, 1);
        Assert.Equal(Vector(ab, "actionPoint"), Vector(ba, "actionPoint"));
        Assert.Equal(("body", "body"), (Part(ba, "partA"), Part(ba, "partB")));
    }

    [Fact]
    public void AFishOfAnotherSizeUsesThatSize()
    {
        // L = 200, W = 60: the body's left side is z = −30; its left fin ends at x = L/4 = 50.
        var answer = Answer(Pair(Fish(0, 0, 0, size: [200, 60, 30, 88, 66, 55]), Circle(90, -86, 58)));
        var deployed = Answer(Pair(Fish(0, 0, 0), Circle(90, -86, 58)));

        AssertResult(answer, [0, 2, 0, 1, 90, -29], "large fish");
        Assert.Equal("body", Part(answer, "partA"));
        Assert.False(deployed.GetProperty("intersect").GetBoolean());
    }

    [Fact]
    public void PairsWithAFishWriteBothPartsAndPairsWithoutAFishWriteNeither()
    {
        var run = CliRun.Collide(Pairs(
            Pair(Circle(0, 0, 1), Circle(1, 0, 1)),
            Pair(Fish(0, 0, 0), Circle(70, -78.5, 58)),
            Pair(Fish(0, 0, 0), Circle(1000, 0, 10)),
            Pair(Fish(0, 0, 0), Fish(1000, 0, 0)),
            Pair(Segment(0, 0, 1, 1), Aabb(5, 5, 6, 6))));

        Assert.Equal((0, string.Empty), (run.ExitCode, run.Stderr));
        var answers = JsonDocument.Parse(run.Stdout).RootElement;
        string[] plain = ["intersect", "mtv", "normal", "actionPoint"];
        string[] withParts = ["intersect", "mtv", "normal", "actionPoint", "partA", "partB"];
        Assert.Equal(plain, ShapesCommandTests.Keys(answers[0]));
        Assert.Equal(withParts, ShapesCommandTests.Keys(answers[1]));
        Assert.Equal(withParts, ShapesCommandTests.Keys(answers[2]));
        Assert.Equal(withParts, ShapesCommandTests.Keys(answers[3]));
        Assert.Equal(plain, ShapesCommandTests.Keys(answers[4]));
        Assert.Contains(
            "{\"intersect\":true,\"mtv\":[0,2],\"normal\":[0,1],\"actionPoint\":[70,-21.5],\"partA\":\"body\",\"partB\":null}",
            run.Stdout, StringComparison.Ordinal);

        // No contact: both parts null, even for fish sides.
        Assert.Contains(
            "{\"intersect\":false,\"mtv\":[0,0],\"normal\":[0,0],\"actionPoint\":[0,0],\"partA\":null,\"partB\":null}",
            run.Stdout, StringComparison.Ordinal);
    }

    [Fact]
    public void EveryPartNameCanBeReported()
    {
        // A small ball on the outside of each leaf of a θ = 0 fish, found by the part itself.
        var fish = new FishModel(FishSize.Default, new FishPose(Vector2.Zero, 0f));
        var seen = new HashSet<string>();
        for (var part = FishPart.LeftPectoral; part <= FishPart.RightCaudal; part++)
        {
            var leaf = fish.GetLeaf(part);
            Vector2 centroid = Vector2.Zero;
            foreach (var v in leaf)
            {
                centroid += v / leaf.Length;
            }

            var answer = Answer(Pair(Fish(0, 0, 0), Circle(centroid.X, centroid.Y, 0.5)));
            Assert.True(answer.GetProperty("intersect").GetBoolean(), $"no contact inside {part}");
            seen.Add(Part(answer, "partA")!);
        }

        Assert.Equal<string>(ReferenceFish.PartNames, [.. seen]);
    }

    [Fact]
    public void AnswersEqualFishCollisionCalledDirectlyOnRandomPairsOfEveryKind()
    {
        var random = new Random(31337);
        var pairs = new List<string>();
        var expected = new List<FishContact>();
        for (int i = 0; i < 600; i++)
        {
            var (aText, aFish, aShape) = RandomSide(random, forceFish: i % 3 != 2);
            var (bText, bFish, bShape) = RandomSide(random, forceFish: i % 3 == 0);
            pairs.Add(Pair(aText, bText));
            expected.Add((aFish, bFish) switch
            {
                ({ } fa, { } fb) => FishCollision.Detect(fa, fb),
                ({ } fa, null) => FishCollision.Detect(fa, bShape),
                (null, { } fb) => FishCollision.Detect(aShape, fb),
                _ => new FishContact(CollisionDetector.Detect(aShape, bShape), null, null),
            });
        }

        var run = CliRun.Collide(Pairs([.. pairs]));

        Assert.Equal((0, string.Empty), (run.ExitCode, run.Stderr));
        var answers = JsonDocument.Parse(run.Stdout).RootElement;
        Assert.Equal(expected.Count, answers.GetArrayLength());
        int hits = 0;
        for (int i = 0; i < expected.Count; i++)
        {
            try
            {
                var e = expected[i];
                var a = answers[i];
                hits += e.Intersect ? 1 : 0;
                Assert.Equal(e.Intersect, a.GetProperty("intersect").GetBoolean());
                Assert.Equal(Floats(e.Result.MinimumTranslationVector), Floats(a, "mtv"));
                Assert.Equal(Floats(e.Result.NormalAxis), Floats(a, "normal"));
                Assert.Equal(Floats(e.Result.ActionPoint), Floats(a, "actionPoint"));
                if (a.TryGetProperty("partA", out _))
                {
                    Assert.Equal(Name(e.PartA), Part(a, "partA"));
                    Assert.Equal(Name(e.PartB), Part(a, "partB"));
                }
            }
            catch (XunitException e)
            {
                throw RandomCaseException.At(31337, i, e);
            }
        }

        Assert.InRange(hits, 150, 500);
    }

    [Fact]
    public void FishBallAnswersAgreeWithBruteForceOverTheReferenceLeaves()
    {
        // Independent truth: the reference's leaf polygons (ReferenceFish, from the formulas) and
        // point–polygon distances in double. A ball intersects the fish when its centre is nearer
        // than its radius to some leaf; the part named must be such a leaf, and when the centre is
        // outside that leaf the depth |mtv| is the radius minus the distance.
        const int seed = 8086;
        var random = new Random(seed);
        var cases = new List<(double[] Pose, double X, double Z, double R)>();
        for (int i = 0; i < 400; i++)
        {
            cases.Add(([F(random, -100, 100), F(random, -100, 100), F(random, -4, 4), F(random, -1, 1), F(random, -1, 1), F(random, -1, 1)],
                F(random, -220, 220), F(random, -220, 220), F(random, 10, 80)));
        }

        var run = CliRun.Collide(Pairs([.. cases.Select(c => Pair(Fish(c.Pose[0], c.Pose[1], c.Pose[2], c.Pose[3], c.Pose[4], c.Pose[5]), Circle(c.X, c.Z, c.R)))]));

        Assert.Equal((0, string.Empty), (run.ExitCode, run.Stderr));
        var answers = JsonDocument.Parse(run.Stdout).RootElement;
        int hits = 0, misses = 0;
        for (int i = 0; i < cases.Count; i++)
        {
            var (pose, x, z, r) = cases[i];
            string where = $"case {i} (seed {seed}): fish at [{string.Join(", ", pose)}], ball ({x}, {z}) r {r}";
            var leaves = ReferenceFish.Leaves(ReferenceFish.DeployedSize, (float)pose[0], (float)pose[1], (float)pose[2], (float)pose[3], (float)pose[4], (float)pose[5]);
            double[] distance = [.. leaves.Select(leaf => Distance(leaf, (float)x, (float)z))];
            double nearest = distance.Min();
            var answer = answers[i];
            bool intersect = answer.GetProperty("intersect").GetBoolean();
            if (Math.Abs(nearest - (float)r) < 1e-2)
            {
                continue; // grazing: either answer is within round-off
            }

            Assert.True(intersect == nearest < (float)r, $"{where}: intersect {intersect}, but the nearest leaf is {nearest} from the centre");
            if (!intersect)
            {
                misses++;
                continue;
            }

            hits++;
            int part = Array.IndexOf(ReferenceFish.PartNames, Part(answer, "partA"));
            Assert.True(part >= 0 && distance[part] < (float)r + 1e-2, $"{where}: part {Part(answer, "partA")} is {(part >= 0 ? distance[part] : double.NaN)} from the centre");
            if (distance[part] > 1e-3)
            {
                var (mx, mz) = Vector(answer, "mtv");
                double depth = Math.Sqrt((mx * mx) + (mz * mz));
                Assert.True(Math.Abs(depth - ((float)r - distance[part])) < 1e-2, $"{where}: depth {depth}, expected {(float)r - distance[part]} on {Part(answer, "partA")}");
            }
        }

        Assert.InRange(hits, 60, 340);
        Assert.InRange(misses, 60, 340);
    }

    // Distance from a point to a convex polygon (0 inside), in double.
    private static double Distance((double X, double Z)[] polygon, double x, double z)
    {
        bool inside = true;
        double best = double.PositiveInfinity;
        double orientation = 0;
        for (int k = 0; k < polygon.Length; k++)
        {
            var (ax, az) = polygon[k];
            var (bx, bz) = polygon[(k + 1) % polygon.Length];
            orientation += (ax * bz) - (bx * az);
        }

        for (int k = 0; k < polygon.Length; k++)
        {
            var (ax, az) = polygon[k];
            var (bx, bz) = polygon[(k + 1) % polygon.Length];
            double ex = bx - ax, ez = bz - az;
            double cross = (ex * (z - az)) - (ez * (x - ax));
            if (cross * orientation < 0)
            {
                inside = false;
            }

            double t = Math.Clamp((((x - ax) * ex) + ((z - az) * ez)) / ((ex * ex) + (ez * ez)), 0, 1);
            double dx = ax + (t * ex) - x, dz = az + (t * ez) - z;
            best = Math.Min(best, Math.Sqrt((dx * dx) + (dz * dz)));
        }

        return inside ? 0 : best;
    }

    private static (string Text, FishModel? Fish, Shape Shape) RandomSide(Random random, bool forceFish)
    {
        float x = F(random, -150, 150), z = F(random, -150, 150);
        int kind = forceFish ? 5 : random.Next(6);
        switch (kind)
        {
            case 0:
                float r = F(random, 5, 80);
                return (Circle(x, z, r), null, new Circle(new Vector2(x, z), r));
            case 1:
                float w = F(random, 5, 150), h = F(random, 5, 150);
                return (Aabb(x, z, x + w, z + h), null, new Aabb(new Vector2(x, z), new Vector2(x + w, z + h)));
            case 2:
                float[] min = [x - 40, z - 40, ((x + z) * MathF.Sqrt(0.5f)) - 30, ((x - z) * MathF.Sqrt(0.5f)) - 30];
                float[] max = [x + 40, z + 40, ((x + z) * MathF.Sqrt(0.5f)) + 30, ((x - z) * MathF.Sqrt(0.5f)) + 30];
                return (KDop8(Array.ConvertAll(min, v => (double)v), Array.ConvertAll(max, v => (double)v)), null, new KDop8(min, max));
            case 3:
                Vector2[] triangle = [new(x, z), new(x + F(random, 20, 90), z + F(random, -10, 10)), new(x + F(random, -10, 10), z + F(random, 20, 90))];
                return (Polygon(Array.ConvertAll(triangle, v => ((double)v.X, (double)v.Y))), null, new ConvexPolygon(triangle));
            case 4:
                float bx = x + F(random, -120, 120), bz = z + F(random, -120, 120);
                return (Segment(x, z, bx, bz), null, new Segment(new Vector2(x, z), new Vector2(bx, bz)));
            default:
                float heading = F(random, -4, 4), j1 = F(random, -1, 1), j2 = F(random, -1, 1), j3 = F(random, -1, 1);
                var model = new FishModel(FishSize.Default, new FishPose(new Vector2(x, z), heading, j1, j2, j3));
                return (Fish(x, z, heading, j1, j2, j3), model, default);
        }
    }

    private static float F(Random random, double lo, double hi) => (float)(lo + ((hi - lo) * random.NextDouble()));

    private static string? Name(FishPart? part) => part is { } p ? ReferenceFish.PartNames[(int)p] : null;

    private static float[] Floats(Vector3 v) => [v.X == 0f ? 0f : v.X, v.Z == 0f ? 0f : v.Z];

    private static float[] Floats(JsonElement answer, string field) =>
        [answer.GetProperty(field)[0].GetSingle(), answer.GetProperty(field)[1].GetSingle()];

    private static JsonElement Answer(string pairs)
    {
        var run = CliRun.Collide("[" + pairs + "]");
        Assert.True(run.ExitCode == 0, run.Stderr);
        return JsonDocument.Parse(run.Stdout).RootElement[0].Clone();
    }

    private static string? Part(JsonElement answer, string field) => answer.GetProperty(field).GetString();

    private static (double X, double Z) Vector(JsonElement answer, string field) =>
        (answer.GetProperty(field)[0].GetDouble(), answer.GetProperty(field)[1].GetDouble());

    private static void AssertVector(JsonElement answer, string field, double x, double z)
    {
        var (ax, az) = Vector(answer, field);
        Assert.True(Math.Abs(ax - x) <= Tolerance && Math.Abs(az - z) <= Tolerance, $"{field} is [{ax}, {az}], expected [{x}, {z}]");
    }

    private static void AssertResult(JsonElement answer, double[] expected, string what)
    {
        Assert.True(answer.GetProperty("intersect").GetBoolean(), what + ": no intersection");
        AssertVector(answer, "mtv", expected[0], expected[1]);
        AssertVector(answer, "normal", expected[2], expected[3]);
        AssertVector(answer, "actionPoint", expected[4], expected[5]);
    }
}
