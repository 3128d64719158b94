namespace URWPGSim2D.Collision.Tests.NarrowPhase;

/// <summary>
/// <see cref="CircleLanes"/> takes a different road for each Voronoi region of the picked face:
/// inside the polygon or over the face it reads the face's normal straight from the lanes, beyond
/// one of the face's ends it takes the square root and the divisions (or finds the vertex out of
/// reach), and apart from that the chord's far end is −r or the greatest −s/d. Every road must give
/// the scalar path's floats bit for bit; these tests draw pairs that take each road many times
/// (counted, so a road that stops being taken fails the test) and the exact cases where roads meet:
/// ties between faces, a centre on a face's line or on a vertex, a vertex exactly at the reach.
/// </summary>
public sealed class CircleLanesTests
{
    [Fact]
    public void EveryRoadEqualsTheScalarPathBitForBit()
    {
        // As in a crowd of large circles against small polygons (and the Box2D comparison's
        // pairs): polygons of 3 to 8 vertices on an ellipse 50 to 500 mm across, circles of
        // 25 to 250 mm with their centre up to the sum of the two radii from the polygon's.
        const int seed = 1014;
        var rng = new Random(seed);
        int apart = 0, outOfReach = 0, inside = 0, face = 0, vertex = 0, farEnd = 0;
        for (int trial = 0; trial < 20000; trial++)
        {
            var polygon = EllipsePolygon(rng, out Vector2 centre, out float size);
            float r = 25f + (225f * rng.NextSingle());
            float reach = (size + r) * rng.NextSingle(), angle = 2f * MathF.PI * rng.NextSingle();
            var circle = new Circle(centre + (reach * new Vector2(MathF.Cos(angle), MathF.Sin(angle))), r);
            try
            {
                var view = polygon.View();
                var scalar = CircleConvex.Detect(circle, view, vector: false);
                BitExact.AssertSame(scalar, CollisionDetector.Detect(circle, polygon));
                BitExact.AssertSame(scalar.Swapped(), CollisionDetector.Detect(polygon, circle));
                BitExact.AssertSame(scalar, CircleConvex.Detect(circle, view));
                if (PolygonLanes.IsSupported)
                {
                    BitExact.AssertSame(scalar, CircleLanes.Detect(circle, view));
                }
            }
            catch (XunitException e)
            {
                throw RandomCaseException.At(seed, trial, new XunitException($"{Show(circle, polygon)}: {e.Message}"));
            }

            switch (Road(circle, polygon))
            {
                case Roads.Apart: apart++; break;
                case Roads.OutOfReach: outOfReach++; break;
                case Roads.Inside: inside++; break;
                case Roads.Face: face++; break;
                case Roads.Vertex: vertex++; break;
            }

            farEnd += FarEndInside(circle, polygon) ? 1 : 0;
        }

        Assert.InRange(apart, 2000, 5000);
        Assert.InRange(outOfReach, 200, 1000);
        Assert.InRange(inside, 3000, 7000);
        Assert.InRange(face, 5000, 9000);
        Assert.InRange(vertex, 3000, 6000);
        Assert.InRange(farEnd, 5000, 11000);
    }

    [Fact]
    public void TiesZerosAndTheExactReachOnTheIntegerGridEqualTheScalarPath()
    {
        // Integer polygons and every centre on a half-unit grid around them: the centre on a
        // face's line (a greatest separation of ±0), on a vertex, on a diagonal (two faces tie:
        // the lower index wins), a vertex exactly at the reach (3-4-5: |c − v|² = r², apart).
        Vector2[][] outlines =
        [
            [new(0, 0), new(10, 0), new(10, 10), new(0, 10)],
            [new(0, 0), new(8, 0), new(0, 6)],
            [new(0, -5), new(5, 0), new(0, 5), new(-5, 0)],
            [new(2, 0), new(6, 0), new(8, 2), new(8, 6), new(6, 8), new(2, 8), new(0, 6), new(0, 2)],
            [new(0, 0), new(4, 0), new(7, 3), new(7, 7), new(4, 9)],
        ];
        float[] radii = [0.5f, 1f, 2f, 5f, 7.5f];
        int ties = 0, onLine = 0, atReach = 0, hits = 0;
        foreach (var outline in outlines)
        {
            var polygon = new ConvexPolygon(outline);
            var view = polygon.View();
            for (int ix = -32; ix <= 40; ix++)
            {
                for (int iz = -32; iz <= 40; iz++)
                {
                    var c = new Vector2(ix * 0.5f, iz * 0.5f);
                    foreach (float r in radii)
                    {
                        var circle = new Circle(c, r);
                        var scalar = CircleConvex.Detect(circle, view, vector: false);
                        try
                        {
                            BitExact.AssertSame(scalar, CollisionDetector.Detect(circle, polygon));
                            if (PolygonLanes.IsSupported)
                            {
                                BitExact.AssertSame(scalar, CircleLanes.Detect(circle, view));
                            }
                        }
                        catch (XunitException e)
                        {
                            throw new XunitException($"{Show(circle, polygon)}: {e.Message}");
                        }

                        var s = Separations(circle, polygon);
                        float best = s.Max();
                        ties += s.Count(x => x == best) > 1 ? 1 : 0;
                        onLine += best == 0f ? 1 : 0;
                        atReach += polygon.Vertices.ToArray().Any(v => Vector2.DistanceSquared(c, v) == r * r) ? 1 : 0;
                        hits += scalar.Intersect ? 1 : 0;
                    }
                }
            }
        }

        Assert.True(ties > 1000, $"{ties} ties");
        Assert.True(onLine > 500, $"{onLine} centres on a face's line");
        Assert.True(atReach > 100, $"{atReach} vertices exactly at the reach");
        Assert.True(hits > 10000, $"{hits} contacts");
    }

    [Fact]
    public void ATieGoesToTheLowerFace()
    {
        // The corner (10, 10) of the square, radius 2: the right face (index 1) and the top face
        // (index 2) both pass through the centre (separation 0). The right face wins: the MTV is
        // 2 along +x, and the chord on the line z = 10 is [−2, 0] (the circle's deepest point
        // (8, 10) lies on the top face, not outside it): the action point is (9, 10).
        var square = new ConvexPolygon([new(0, 0), new(10, 0), new(10, 10), new(0, 10)]);
        var result = CollisionDetector.Detect(new Circle(new(10, 10), 2), square);
        Assert.True(result.Intersect);
        Assert.Equal(new Vector3(2, 0, 0), result.MinimumTranslationVector);
        Assert.Equal(new Vector3(1, 0, 0), result.NormalAxis);
        Assert.Equal(new Vector3(9, 0, 10), result.ActionPoint);
    }

    private enum Roads
    {
        Apart,
        OutOfReach,
        Inside,
        Face,
        Vertex,
    }

    // The road the kernel takes, worked out beside it: the greatest separation decides apart
    // (≥ r) or inside (≤ 0); otherwise a face region keeps that face's normal, a vertex region
    // has another, and a vertex out of reach leaves no contact.
    private static Roads Road(in Circle circle, in ConvexPolygon polygon)
    {
        var s = Separations(circle, polygon);
        float best = s.Max();
        if (best >= circle.Radius)
        {
            return Roads.Apart;
        }

        var result = CollisionDetector.Detect(circle, polygon);
        if (!result.Intersect)
        {
            return Roads.OutOfReach;
        }

        if (best <= 0f)
        {
            return Roads.Inside;
        }

        var normal = XZPlane.ToPlane(result.NormalAxis);
        return polygon.Normals[Array.IndexOf(s, best)] == normal ? Roads.Face : Roads.Vertex;
    }

    // Whether the contact's chord has its far end inside the circle: the circle's deepest point
    // c − r·normal lies outside some face.
    private static bool FarEndInside(in Circle circle, in ConvexPolygon polygon)
    {
        var result = CollisionDetector.Detect(circle, polygon);
        if (!result.Intersect)
        {
            return false;
        }

        var deepest = circle.Center - (circle.Radius * XZPlane.ToPlane(result.NormalAxis));
        var v = polygon.Vertices;
        var n = polygon.Normals;
        for (int i = 0; i < v.Length; i++)
        {
            if (Vector2.Dot(n[i], deepest - v[i]) > 1e-3f)
            {
                return true;
            }
        }

        return false;
    }

    // Every face's separation n·(c − v), as the kernels compute it.
    private static float[] Separations(in Circle circle, in ConvexPolygon polygon)
    {
        var v = polygon.Vertices;
        var n = polygon.Normals;
        var s = new float[v.Length];
        for (int i = 0; i < v.Length; i++)
        {
            s[i] = (n[i].X * (circle.Center.X - v[i].X)) + (n[i].Y * (circle.Center.Y - v[i].Y));
        }

        return s;
    }

    // A convex polygon of 3 to 8 vertices at sorted random angles on an ellipse 50 to 500 mm
    // across (aspect 0.6 to 1, turned at random) within ±1,500 mm; its ellipse centre and
    // half-diameter (the farthest a vertex can be from that centre).
    private static ConvexPolygon EllipsePolygon(Random rng, out Vector2 centre, out float size)
    {
        while (true)
        {
            int count = rng.Next(3, 9);
            size = 25f + (225f * rng.NextSingle());
            float aspect = 0.6f + (0.4f * rng.NextSingle()), turn = 2f * MathF.PI * rng.NextSingle();
            centre = new Vector2(3000f * (rng.NextSingle() - 0.5f), 2000f * (rng.NextSingle() - 0.5f));
            var angles = Enumerable.Range(0, count).Select(_ => 2f * MathF.PI * rng.NextSingle()).Order().ToArray();
            var (sin, cos) = MathF.SinCos(turn);
            var points = new Vector2[count];
            for (int i = 0; i < count; i++)
            {
                float ex = size * MathF.Cos(angles[i]), ez = size * aspect * MathF.Sin(angles[i]);
                points[i] = centre + new Vector2((cos * ex) - (sin * ez), (sin * ex) + (cos * ez));
            }

            try
            {
                return new ConvexPolygon(points);
            }
            catch (ArgumentException)
            {
                // Two angles too close (a repeated or collinear vertex): draw again.
            }
        }
    }

    private static string Show(in Circle circle, in ConvexPolygon polygon) =>
        $"circle ({circle.Center.X:R}, {circle.Center.Y:R}) r {circle.Radius:R} vs polygon [{string.Join(", ", polygon.Vertices.ToArray().Select(v => $"({v.X:R}, {v.Y:R})"))}]";
}
