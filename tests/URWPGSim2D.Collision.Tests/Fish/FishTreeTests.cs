namespace URWPGSim2D.Collision.Tests.Fish;

/// <summary>
/// The bounding-volume tree never changes an answer: for thousands of random poses and
/// partners, the tree query equals brute force over every leaf (no pruning), both with the
/// same leaf routines (exactly equal) and with independent polygons through
/// <see cref="CollisionDetector"/> (equal depth and part, up to round-off).
/// </summary>
public class FishTreeTests
{
    private const int Cases = 3000;
    private const float Tolerance = 1e-3f;

    private delegate CollisionDetectionResult LeafTest(in ConvexView leaf);

    private delegate int AllTest(Span<FishContact> contacts);

    [Fact]
    public void CircleQueriesEqualBruteForce() => Check(31, FishTestKit.Circle,
        (f, b) => FishCollision.Detect(f, b), (b, f) => FishCollision.Detect(b, f),
        b => (in ConvexView leaf) => CircleConvex.Detect(b, leaf).Swapped(),
        (leaf, b) => CollisionDetector.Detect(leaf, b),
        (f, b, s) => FishCollision.DetectAll(f, b, s), (b, f, s) => FishCollision.DetectAll(b, f, s));

    [Fact]
    public void BoxQueriesEqualBruteForce() => Check(32, FishTestKit.Aabb,
        (f, b) => FishCollision.Detect(f, b), (b, f) => FishCollision.Detect(b, f),
        b => (in ConvexView leaf) =>
        {
            Span<Vector2> corners = stackalloc Vector2[4];
            b.WriteVertices(corners);
            return ConvexSat.Detect(leaf, Aabb.View(corners));
        },
        (leaf, b) => CollisionDetector.Detect(leaf, b),
        (f, b, s) => FishCollision.DetectAll(f, b, s), (b, f, s) => FishCollision.DetectAll(b, f, s));

    [Fact]
    public void KDopQueriesEqualBruteForce() => Check(33, (r, _) => FishTestKit.KDop(r, 300f),
        (f, b) => FishCollision.Detect(f, b), (b, f) => FishCollision.Detect(b, f),
        b => (in ConvexView leaf) => ConvexSat.Detect(leaf, b.View()),
        (leaf, b) => CollisionDetector.Detect(leaf, b),
        (f, b, s) => FishCollision.DetectAll(f, b, s), (b, f, s) => FishCollision.DetectAll(b, f, s));

    [Fact]
    public void PolygonQueriesEqualBruteForce() => Check(34, FishTestKit.Polygon,
        (f, b) => FishCollision.Detect(f, b), (b, f) => FishCollision.Detect(b, f),
        b => (in ConvexView leaf) => ConvexSat.Detect(leaf, b.View()),
        (leaf, b) => CollisionDetector.Detect(leaf, b),
        (f, b, s) => FishCollision.DetectAll(f, b, s), (b, f, s) => FishCollision.DetectAll(b, f, s));

    [Fact]
    public void SegmentQueriesEqualBruteForce() => Check(35, (r, _) => FishTestKit.Segment(r, 250f),
        (f, b) => FishCollision.Detect(f, b), (b, f) => FishCollision.Detect(b, f),
        b => (in ConvexView leaf) =>
        {
            Span<Vector2> v = stackalloc Vector2[2];
            Span<Vector2> n = stackalloc Vector2[2];
            b.WriteView(v, n);
            return ConvexSat.Detect(leaf, Segment.View(v, n));
        },
        (leaf, b) => CollisionDetector.Detect(leaf, b),
        (f, b, s) => FishCollision.DetectAll(f, b, s), (b, f, s) => FishCollision.DetectAll(b, f, s));

    [Fact]
    public void DeepestFishContactEqualsBruteForceWhenManyLeafPairsOverlapAlike()
    {
        // Fish almost on top of each other, near the origin and 20 m away: many leaf pairs
        // overlap with close depths, the case where stopping early on the depth bound could go wrong.
        var rng = new Random(37);
        var a = new FishModel(FishSize.Default, default);
        var b = new FishModel(FishSize.Default, default);
        for (int trial = 0; trial < 3000; trial++)
        {
            if (trial % 500 == 499)
            {
                var size = FishTestKit.Size(rng);
                a = new FishModel(size, default);
                b = new FishModel(size, default);
            }

            Vector2 far = trial % 2 == 0 ? Vector2.Zero : new Vector2(20000f, -15000f);
            var pose = FishTestKit.Pose(rng, trial % 3 == 0 ? MathF.PI : 0.5f, 50f).Translated(far);
            float shift = trial % 4 == 0 ? 0f : FishTestKit.Range(rng, 0f, 20f);
            var other = new FishPose(pose.Position + FishTestKit.Point(rng, shift), pose.Heading + FishTestKit.Range(rng, -0.2f, 0.2f), pose.Joint1, pose.Joint2 + 0.1f, pose.Joint3);
            if (trial % 5 == 0)
            {
                // Axis-aligned and straight, shifted along x: depths equal to slab overlaps.
                pose = new FishPose(pose.Position, 0f);
                other = new FishPose(pose.Position + new Vector2(FishTestKit.Range(rng, -30f, 30f), 0f), trial % 10 == 0 ? 0f : MathF.PI);
            }

            a.SetPose(pose);
            b.SetPose(other);
            var expected = FishContact.None;
            float best = -1f;
            for (int la = 0; la < 8; la++)
            {
                for (int lb = 0; lb < 8; lb++)
                {
                    var r = ConvexSat.Detect(a.LeafView(la), b.LeafView(lb));
                    if (r.Intersect && r.MinimumTranslationVector.LengthSquared() > best)
                    {
                        best = r.MinimumTranslationVector.LengthSquared();
                        expected = new FishContact(r, (FishPart)la, (FishPart)lb);
                    }

                    if (r.Intersect)
                    {
                        // The bound the search stops on holds every computed depth.
                        float bound = FishTree.DepthBound(a.LeafMin(la), a.LeafMax(la), b.LeafMin(lb), b.LeafMax(lb));
                        Assert.True(r.Depth <= bound, $"trial {trial} {la}/{lb}: depth {r.Depth} above its bound {bound}");
                    }
                }
            }

            var tree = FishCollision.Detect(a, b);
            Assert.True(expected == tree, $"trial {trial}: tree {tree} vs brute force {expected}");
        }
    }

    [Fact]
    public void FishQueriesEqualBruteForce()
    {
        var rng = new Random(36);
        var a = new FishModel(FishSize.Default, default);
        var b = new FishModel(FishSize.Default, default);
        var all = new FishContact[FishCollision.MaxContactsWithFish];
        int hits = 0, prunedMisses = 0;
        for (int trial = 0; trial < Cases; trial++)
        {
            a.SetPose(FishTestKit.Pose(rng, trial % 3 == 0 ? MathF.PI : 0.8f, 100f));
            b.SetPose(FishTestKit.Pose(rng, trial % 3 == 1 ? MathF.PI : 0.8f, 450f));
            var tree = FishCollision.Detect(a, b);

            // Brute force with the same leaf routine: every leaf pair, deepest, ties to the lower pair.
            var expected = FishContact.None;
            float best = -1f;
            var list = new List<FishContact>();
            for (int la = 0; la < 8; la++)
            {
                for (int lb = 0; lb < 8; lb++)
                {
                    var r = ConvexSat.Detect(a.LeafView(la), b.LeafView(lb));
                    if (!r.Intersect)
                    {
                        continue;
                    }

                    var c = new FishContact(r, (FishPart)la, (FishPart)lb);
                    list.Add(c);
                    if (r.MinimumTranslationVector.LengthSquared() > best)
                    {
                        best = r.MinimumTranslationVector.LengthSquared();
                        expected = c;
                    }
                }
            }

            Assert.True(expected == tree, $"trial {trial}: tree {tree} vs brute force {expected}");
            var back = FishCollision.Detect(b, a);
            Assert.True(MathF.Abs(back.Result.Depth - tree.Result.Depth) <= Tolerance, $"trial {trial}: b–a depth {back.Result.Depth} vs a–b {tree.Result.Depth}");
            int n = FishCollision.DetectAll(a, b, all);
            AssertSameContacts(list, all.AsSpan(0, n), trial);

            // Independent: validated polygons through the public narrow phase.
            var polysA = FishTestKit.LeafPolygons(a);
            var polysB = FishTestKit.LeafPolygons(b);
            float maxDepth = 0f;
            var depth = new float[8, 8];
            for (int la = 0; la < 8; la++)
            {
                for (int lb = 0; lb < 8; lb++)
                {
                    depth[la, lb] = CollisionDetector.Detect(polysA[la], polysB[lb]).Depth;
                    maxDepth = MathF.Max(maxDepth, depth[la, lb]);
                }
            }

            AssertAgrees(tree.Result, maxDepth, tree.Intersect ? depth[(int)tree.PartA!.Value, (int)tree.PartB!.Value] : 0f, trial);
            hits += tree.Intersect ? 1 : 0;
            prunedMisses += !tree.Intersect && Vector2.Distance(a.Root.Center, b.Root.Center) < a.Root.Radius + b.Root.Radius ? 1 : 0;
        }

        AssertMix(hits, prunedMisses);
    }

    [Fact]
    public void ShapeUnionDispatchesToTheTypedQuery()
    {
        var rng = new Random(37);
        var fish = new FishModel(FishSize.Default, default);
        var contacts = new FishContact[8];
        for (int trial = 0; trial < 500; trial++)
        {
            try
            {
                fish.SetPose(FishTestKit.Pose(rng, 0.8f, 100f));
                Shape[] shapes = [FishTestKit.Circle(rng, 300f), FishTestKit.Aabb(rng, 300f), FishTestKit.KDop(rng, 300f), FishTestKit.Polygon(rng, 300f), FishTestKit.Segment(rng, 300f)];
                Assert.Equal(FishCollision.Detect(fish, shapes[0].AsCircle()), FishCollision.Detect(fish, shapes[0]));
                Assert.Equal(FishCollision.Detect(fish, shapes[1].AsAabb()), FishCollision.Detect(fish, shapes[1]));
                Assert.Equal(FishCollision.Detect(fish, shapes[2].AsKDop8()), FishCollision.Detect(fish, shapes[2]));
                Assert.Equal(FishCollision.Detect(fish, shapes[3].AsPolygon()), FishCollision.Detect(fish, shapes[3]));
                Assert.Equal(FishCollision.Detect(fish, shapes[4].AsSegment()), FishCollision.Detect(fish, shapes[4]));
                foreach (var s in shapes)
                {
                    Assert.Equal(FishCollision.Detect(fish, s).Swapped(), FishCollision.Detect(s, fish));
                    int n = FishCollision.DetectAll(s, fish, contacts);
                    Assert.Equal(FishCollision.DetectAll(fish, s, new FishContact[8]), n);
                }
            }
            catch (XunitException e)
            {
                throw RandomCaseException.At(37, trial, e);
            }
        }
    }

    [Fact]
    public void TooShortSpanThrowsAndNamesIt()
    {
        var fish = new FishModel(FishSize.Default, default);
        var ball = new Circle(Vector2.Zero, 300f); // covers every leaf: 8 contacts
        Assert.Equal(8, FishCollision.DetectAll(fish, ball, new FishContact[8]));
        var e = Assert.Throws<ArgumentException>(() => FishCollision.DetectAll(fish, ball, new FishContact[3]));
        Assert.Equal("contacts", e.ParamName);
    }

    private static void Check<T>(
        int seed,
        Func<Random, float, T> make,
        Func<FishModel, T, FishContact> tree,
        Func<T, FishModel, FishContact> treeSwapped,
        Func<T, LeafTest> leafTest,
        Func<ConvexPolygon, T, CollisionDetectionResult> independent,
        Func<FishModel, T, FishContact[], int> detectAll,
        Func<T, FishModel, FishContact[], int> detectAllSwapped)
    {
        var rng = new Random(seed);
        var fish = new FishModel(FishSize.Default, default);
        var all = new FishContact[FishCollision.MaxContactsWithShape];
        int hits = 0, prunedMisses = 0;
        for (int trial = 0; trial < Cases; trial++)
        {
            if (trial % 1000 == 999)
            {
                fish = new FishModel(FishTestKit.Size(rng), default);
            }

            fish.SetPose(FishTestKit.Pose(rng, trial % 3 == 0 ? MathF.PI : 0.8f, 100f));
            T shape = make(rng, 380f);
            var result = tree(fish, shape);

            var test = leafTest(shape);
            var expected = FishContact.None;
            float best = -1f;
            var list = new List<FishContact>();
            for (int leaf = 0; leaf < 8; leaf++)
            {
                var r = test(fish.LeafView(leaf));
                if (r.Intersect)
                {
                    var c = new FishContact(r, (FishPart)leaf, null);
                    list.Add(c);
                    if (r.MinimumTranslationVector.LengthSquared() > best)
                    {
                        best = r.MinimumTranslationVector.LengthSquared();
                        expected = c;
                    }
                }
            }

            Assert.True(expected == result, $"trial {trial}: tree {result} vs brute force {expected}");
            Assert.Equal(result.Swapped(), treeSwapped(shape, fish));
            int n = detectAll(fish, shape, all);
            AssertSameContacts(list, all.AsSpan(0, n), trial);
            Assert.Equal(n, detectAllSwapped(shape, fish, all));
            for (int i = 0; i < n; i++)
            {
                Assert.Equal(list[i].Swapped(), all[i]);
            }

            var polygons = FishTestKit.LeafPolygons(fish);
            float maxDepth = 0f;
            var depth = new float[8];
            for (int leaf = 0; leaf < 8; leaf++)
            {
                depth[leaf] = independent(polygons[leaf], shape).Depth;
                maxDepth = MathF.Max(maxDepth, depth[leaf]);
            }

            AssertAgrees(result.Result, maxDepth, result.Intersect ? depth[(int)result.PartA!.Value] : 0f, trial);
            Assert.Null(result.PartB);
            hits += result.Intersect ? 1 : 0;
            var bound = Circle(shape);
            prunedMisses += !result.Intersect && Vector2.Distance(fish.Root.Center, bound.Center) < fish.Root.Radius + bound.Radius ? 1 : 0;
        }

        AssertMix(hits, prunedMisses);
    }

    private static Circle Circle<T>(T shape) => shape switch
    {
        Circle c => c,
        Aabb b => b.BoundingCircle,
        KDop8 k => k.BoundingCircle,
        ConvexPolygon p => p.BoundingCircle,
        Segment s => s.BoundingCircle,
        _ => throw new ArgumentException("unknown shape", nameof(shape)),
    };

    // The tree's deepest depth equals the independent maximum, and its part reaches it.
    private static void AssertAgrees(CollisionDetectionResult tree, float maxDepth, float depthAtPart, int trial)
    {
        if (maxDepth > Tolerance || tree.Depth > Tolerance)
        {
            Assert.True(tree.Intersect, $"trial {trial}: tree missed a contact of depth {maxDepth}");
            Assert.True(MathF.Abs(tree.Depth - maxDepth) <= Tolerance, $"trial {trial}: depth {tree.Depth} vs independent {maxDepth}");
            Assert.True(depthAtPart >= maxDepth - Tolerance, $"trial {trial}: part depth {depthAtPart} vs deepest {maxDepth}");
        }
    }

    private static void AssertSameContacts(List<FishContact> expected, ReadOnlySpan<FishContact> actual, int trial)
    {
        Assert.True(expected.Count == actual.Length, $"trial {trial}: {actual.Length} contacts written, brute force finds {expected.Count}");
        var remaining = new List<FishContact>(expected);
        foreach (var c in actual)
        {
            Assert.True(remaining.Remove(c), $"trial {trial}: contact {c} is not a brute-force contact");
        }
    }

    private static void AssertMix(int hits, int prunedMisses)
    {
        // Neither a test of hits only nor of misses only: both kinds, and misses the root did not prune.
        Assert.InRange(hits, Cases / 6, Cases * 5 / 6);
        Assert.True(prunedMisses > Cases / 20, $"only {prunedMisses} misses got past the root");
    }
}
