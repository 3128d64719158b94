namespace URWPGSim2D.Collision.Tests.Pool;

public class FieldContainmentTests
{
    private readonly Field _field = new();

    [Fact]
    public void CircleInsideOrTouchingIsContained()
    {
        Assert.False(_field.Contain(new Circle(Vector2.Zero, 58f)).Intersect);
        Assert.False(_field.Contain(new Circle(new Vector2(1442f, 942f), 58f)).Intersect);
        Assert.False(_field.Contain(new Circle(new Vector2(-1442f, -942f), 58f)).Intersect);
    }

    [Fact]
    public void CircleThroughTheRightWallIsPushedBackAlongMinusX()
    {
        var r = _field.Contain(new Circle(new Vector2(1452f, 300f), 58f));
        Assert.True(r.Intersect);
        AssertVector(new Vector3(-10f, 0f, 0f), r.MinimumTranslationVector);
        AssertVector(new Vector3(-1f, 0f, 0f), r.NormalAxis);
        AssertVector(new Vector3(1500f, 0f, 300f), r.ActionPoint);
    }

    [Fact]
    public void CircleThroughTheTopWallIsPushedBackAlongPlusZ()
    {
        var r = _field.Contain(new Circle(new Vector2(-200f, -980f), 58f));
        AssertVector(new Vector3(0f, 0f, 38f), r.MinimumTranslationVector);
        AssertVector(new Vector3(0f, 0f, 1f), r.NormalAxis);
        AssertVector(new Vector3(-200f, 0f, -1000f), r.ActionPoint);
    }

    [Fact]
    public void CircleInACornerLeavesBothWalls()
    {
        var r = _field.Contain(new Circle(new Vector2(-1470f, 990f), 40f));
        AssertVector(new Vector3(10f, 0f, -30f), r.MinimumTranslationVector);
        Assert.Equal(MathF.Sqrt(1000f), r.Depth, 1e-3f);
    }

    [Fact]
    public void GoalMouthIsOpenUpToTheBackWall()
    {
        // A ball deep in the right goal, touching the back wall: inside the pool.
        Assert.False(_field.Contain(new Circle(new Vector2(1442f, 0f), 58f)).Intersect);

        // Past the back wall it is pushed back, along −X only.
        var r = _field.Contain(new Circle(new Vector2(1460f, 100f), 58f));
        AssertVector(new Vector3(-18f, 0f, 0f), r.MinimumTranslationVector);
    }

    [Fact]
    public void PointsOutsideArePushedBackByTheirExtremes()
    {
        Vector2[] triangle = [new(1490f, 0f), new(1530f, 10f), new(1480f, 40f)];
        var r = _field.Contain(triangle);
        AssertVector(new Vector3(-30f, 0f, 0f), r.MinimumTranslationVector);
        AssertVector(new Vector3(1500f, 0f, 10f), r.ActionPoint);
        Assert.False(_field.Contain([new Vector2(0f, 0f), new Vector2(1500f, 1000f)]).Intersect);
        var e = Assert.Throws<ArgumentException>(() => _field.Contain(ReadOnlySpan<Vector2>.Empty));
        Assert.Equal("points", e.ParamName);
        e = Assert.Throws<ArgumentException>(() => _field.Contain([Vector2.Zero, new Vector2(float.NaN, 1f)]));
        Assert.Equal("points", e.ParamName);
        Assert.Contains("points[1]", e.Message, StringComparison.Ordinal);
    }

    [Fact]
    public void AfterTheMtvEveryShapeIsInsideAndNoShorterAxisMoveWouldDo()
    {
        var rng = new Random(51);
        var fields = new[] { new Field(), new Field(4500f, 3000f) };
        int outside = 0;
        for (int trial = 0; trial < 5000; trial++)
        {
            try
            {
                var field = fields[trial % 2];
                float hx = field.Length / 2f, hz = field.Width / 2f;
                var c = new Circle(new Vector2(FishTestKit.Range(rng, -hx - 100f, hx + 100f), FishTestKit.Range(rng, -hz - 100f, hz + 100f)), FishTestKit.Range(rng, 10f, 120f));
                var r = field.Contain(c);
                bool isInside = c.Center.X - c.Radius >= -hx && c.Center.X + c.Radius <= hx && c.Center.Y - c.Radius >= -hz && c.Center.Y + c.Radius <= hz;
                Assert.Equal(!isInside, r.Intersect);
                if (r.Intersect)
                {
                    outside++;
                    var moved = c.Translated(XZPlane(r.MinimumTranslationVector));
                    Assert.True(
                        MathF.Abs(moved.Center.X) + moved.Radius <= hx + 1e-3f && MathF.Abs(moved.Center.Y) + moved.Radius <= hz + 1e-3f,
                        $"trial {trial}: still outside after the MTV");

                    // Each axis moves exactly by its overshoot: the shortest translation that fits.
                    float over = Math.Max(0f, c.Center.X + c.Radius - hx) + Math.Max(0f, -hx - (c.Center.X - c.Radius));
                    Assert.Equal(over, Math.Abs(r.MinimumTranslationVector.X), 1e-3f);
                    Assert.Equal(1f, r.NormalAxis.Length(), 1e-5f);
                }
            }
            catch (XunitException e)
            {
                throw RandomCaseException.At(51, trial, e);
            }
        }

        Assert.InRange(outside, 500, 4500);
    }

    [Fact]
    public void FishOutsideIsBroughtBackWithTheLeafThatSticksOutMost()
    {
        var rng = new Random(52);
        var fish = new FishModel(FishSize.Default, default);
        int outside = 0;
        for (int trial = 0; trial < 3000; trial++)
        {
            try
            {
                var pose = new FishPose(new Vector2(FishTestKit.Range(rng, -1700f, 1700f), FishTestKit.Range(rng, -1200f, 1200f)), FishTestKit.Range(rng, -MathF.PI, MathF.PI), FishTestKit.Range(rng, -0.8f, 0.8f), FishTestKit.Range(rng, -0.8f, 0.8f), FishTestKit.Range(rng, -0.8f, 0.8f));
                fish.SetPose(pose);
                var contact = _field.Contain(fish);
                bool inside = true;
                float deepest = float.NegativeInfinity;
                FishPart deepestPart = FishPart.Body;
                Vector2 n = XZPlane(contact.Result.NormalAxis);
                foreach (var part in FishTestKit.AllParts)
                {
                    foreach (var v in fish.GetLeaf(part))
                    {
                        inside &= MathF.Abs(v.X) <= 1500f && MathF.Abs(v.Y) <= 1000f;
                        if (Vector2.Dot(v, -n) > deepest)
                        {
                            deepest = Vector2.Dot(v, -n);
                            deepestPart = part;
                        }
                    }
                }

                Assert.Equal(!inside, contact.Intersect);
                if (!contact.Intersect)
                {
                    Assert.Null(contact.PartA);
                    continue;
                }

                outside++;
                Assert.Equal(deepestPart, contact.PartA);
                Assert.Null(contact.PartB);
                fish.SetPose(pose.Translated(XZPlane(contact.Result.MinimumTranslationVector)));
                Assert.True(
                    MathF.Max(MathF.Abs(fish.Bounds.Min.X), MathF.Abs(fish.Bounds.Max.X)) <= 1500f + 1e-3f
                    && MathF.Max(MathF.Abs(fish.Bounds.Min.Y), MathF.Abs(fish.Bounds.Max.Y)) <= 1000f + 1e-3f,
                    $"trial {trial}: fish still outside after the MTV: {fish.Bounds.Min} {fish.Bounds.Max}");
            }
            catch (XunitException e)
            {
                throw RandomCaseException.At(52, trial, e);
            }
        }

        Assert.InRange(outside, 300, 2700);
    }

    [Fact]
    public void PointSetContainmentTakesTheExactExtremesWhateverTheCountAndOrder()
    {
        // The extremes are found four points per vector: every count from 1 to 40 (the overlapping
        // last block), signed zeros, points outside on every side; the result must be the one the
        // extremes taken point by point give, to the bit, and the first point that is not finite is
        // named wherever it sits.
        var rng = new Random(53);
        float[] coordinates = [0f, -0f, 1500f, -1500f, 1000f, -1000f, 1600f, -1100f];
        for (int trial = 0; trial < 4000; trial++)
        {
            try
            {
                int n = 1 + (trial % 40);
                var points = new Vector2[n];
                for (int i = 0; i < n; i++)
                {
                    points[i] = rng.Next(3) == 0
                        ? new Vector2(coordinates[rng.Next(coordinates.Length)], coordinates[rng.Next(coordinates.Length)])
                        : new Vector2(FishTestKit.Range(rng, -1700f, 1700f), FishTestKit.Range(rng, -1200f, 1200f));
                }

                Vector2 min = points[0], max = points[0];
                foreach (var p in points)
                {
                    min = new Vector2(MathF.Min(min.X, p.X), MathF.Min(min.Y, p.Y));
                    max = new Vector2(MathF.Max(max.X, p.X), MathF.Max(max.Y, p.Y));
                }

                var expected = _field.Contain([min, max]); // two points: taken one by one
                var actual = _field.Contain(points);
                Assert.Equal(expected.Intersect, actual.Intersect);
                Assert.Equal(expected.MinimumTranslationVector, actual.MinimumTranslationVector);
                Assert.Equal(expected.NormalAxis, actual.NormalAxis);

                int bad = rng.Next(n);
                points[bad] = rng.Next(2) == 0 ? new Vector2(float.NaN, 0f) : new Vector2(0f, float.NegativeInfinity);
                var e = Assert.Throws<ArgumentException>(() => _field.Contain(points));
                Assert.StartsWith($"points[{bad}] must have finite coordinates", e.Message);
            }
            catch (XunitException e)
            {
                throw RandomCaseException.At(53, trial, e);
            }
        }
    }

    [Fact]
    public void BallWhollyInsideAGoalScores()
    {
        Assert.True(_field.IsInGoal(new Circle(new Vector2(1420f, 0f), 58f), out int side));
        Assert.Equal(1, side);
        Assert.True(_field.IsInGoal(new Circle(new Vector2(-1408f, -142f), 58f), out side));
        Assert.Equal(-1, side);

        // On the goal line, or touching a goal block's side, or out of the mouth: no goal.
        Assert.False(_field.IsInGoal(new Circle(new Vector2(1400f, 0f), 58f), out side));
        Assert.Equal(0, side);
        Assert.False(_field.IsInGoal(new Circle(new Vector2(1420f, 150f), 58f), out _));
        Assert.False(_field.IsInGoal(new Circle(new Vector2(0f, 0f), 58f), out _));
        Assert.True(new Field(4500f, 3000f).IsInGoal(new Circle(new Vector2(2160f, 0f), 58f), out side));
        Assert.Equal(1, side);
    }

    private static Vector2 XZPlane(Vector3 v) => new(v.X, v.Z);

    private static void AssertVector(Vector3 expected, Vector3 actual)
    {
        Assert.True(Vector3.Distance(expected, actual) < 1e-3f, $"expected {expected}, got {actual}");
    }
}
