namespace URWPGSim2D.Collision.Tests.NarrowPhase;

/// <summary>
/// The pair kernels' answers are pinned bit for bit to those of the kernels as they were before
/// issue 10's speed work (the code of the git tag benchmark-baseline, which the benchmarks and
/// CircleActionPointTests compile from that tag): a fixed corpus of pairs is
/// run through the public <see cref="CollisionDetector"/> and every float of every result
/// (zero signs included) goes into one FNV-1a digest — except the action points of circle
/// pairs, which issue 10 let move by rounding (the circle's chord is now taken from its contact
/// feature and, when needed, the far side only: <c>NarrowPhase/CircleChord</c>); those are held
/// to lie in both shapes here and to a double-precision reference in
/// <see cref="CircleActionPointTests"/>, and pinned by a digest of their own, taken from the
/// kernels of issue 10's circle chord (main b6e106b), so that they too move only when a change
/// says so. The expected digest was computed at main c60096a, whose
/// kernels gave the frozen digest of every float, by leaving the same action points out. Faster
/// kernels must not move a single bit, because a last-bit difference can change a match (the fish
/// leaves go through these kernels); a change that means to alter answers must say so and
/// recompute the digest from code that equals the frozen copy.
/// </summary>
/// <remarks>
/// The corpus is built with +, −, ×, ÷ and square roots only (no library trigonometry), so it is
/// the same on every platform.
/// </remarks>
public sealed class PairKernelDigestTests
{
    /// <summary>The digest of the frozen kernels' answers over <see cref="Corpus"/>, circle pairs' action points left out.</summary>
    private const ulong FrozenDigest = 0x24ECBE081D273147UL;

    /// <summary>The digest of the circle pairs' action points over <see cref="Corpus"/> as <c>NarrowPhase/CircleChord</c> gives them (main b6e106b).</summary>
    private const ulong CircleActionPointDigest = 0xBF105790EF806D05UL;

    [Fact]
    public void AnswersEqualTheFrozenKernelsBitForBit()
    {
        var digest = new Digest();
        var circleActionPoints = new Digest();
        int hits = 0, circleContacts = 0;
        Corpus((a, b) =>
        {
            var r = CollisionDetector.Detect(a, b);
            bool circle = a.Kind == ShapeKind.Circle || b.Kind == ShapeKind.Circle;
            digest.Add(r, actionPoint: !circle);
            if (circle)
            {
                circleActionPoints.Add(r.ActionPoint);
            }

            hits += r.Intersect ? 1 : 0;
            if (circle && r.Intersect)
            {
                AssertInBoth(r.ActionPoint, a.Kind == ShapeKind.Circle ? a.AsCircle() : b.AsCircle(), a.Kind == ShapeKind.Circle ? b.AsPolygon() : a.AsPolygon());
                circleContacts++;
            }
        });
        Assert.InRange(hits, 4000, 14000);
        Assert.InRange(circleContacts, 1000, 6000);
        Assert.Equal(FrozenDigest.ToString("X16"), digest.Value.ToString("X16"));
        Assert.Equal(CircleActionPointDigest.ToString("X16"), circleActionPoints.Value.ToString("X16"));
    }

    // The action point lies in the circle and in the polygon, within 0.001 mm plus a few float
    // steps at the coordinates' magnitude (the corpus reaches ±25,000 mm, where a float step is 0.002 mm).
    private static void AssertInBoth(Vector3 point, in Circle circle, ConvexPolygon polygon)
    {
        double px = point.X, pz = point.Z;
        double allowed = 1e-3 + (4.8e-7 * Math.Max(Math.Abs(px), Math.Abs(pz)));
        double fromCentre = Math.Sqrt(((px - circle.Center.X) * (px - circle.Center.X)) + ((pz - circle.Center.Y) * (pz - circle.Center.Y)));
        Assert.True(fromCentre <= circle.Radius + allowed, $"action point ({px}, {pz}) is {fromCentre - circle.Radius:G3} mm outside {circle}");
        var v = polygon.Vertices;
        var n = polygon.Normals;
        for (int i = 0; i < v.Length; i++)
        {
            double outside = (n[i].X * (px - v[i].X)) + (n[i].Y * (pz - v[i].Y));
            Assert.True(outside <= allowed, $"action point ({px}, {pz}) is {outside:G3} mm outside face {i} of a polygon of {v.Length} vertices");
        }
    }

    /// <summary>
    /// Calls <paramref name="pair"/> on 18,000 pairs: polygons of 3 to 8 vertices (and some of 12
    /// and 16) against polygons, boxes, 8-DOPs and circles, overlapping, containing, touching on
    /// integer grids and apart, sizes 2 to 1,200 mm, anywhere in ±25,000 mm.
    /// </summary>
    internal static void Corpus(Action<Shape, Shape> pair)
    {
        var rng = new Random(20_261_130);
        for (int i = 0; i < 18000; i++)
        {
            bool grid = i % 6 == 0;
            double size = grid ? 1 : 2 * Math.Pow(600, rng.NextDouble());
            double cx = grid ? rng.Next(-20, 21) : (rng.NextDouble() * 50000) - 25000;
            double cz = grid ? rng.Next(-20, 21) : (rng.NextDouble() * 50000) - 25000;
            var a = Polygon(rng, cx, cz, size, grid);
            double reach = size * (grid ? 8 : 2.2);
            double bx = cx + (grid ? rng.Next(-8, 9) : reach * ((2 * rng.NextDouble()) - 1));
            double bz = cz + (grid ? rng.Next(-8, 9) : reach * ((2 * rng.NextDouble()) - 1));
            double bSize = grid ? 1 : size * Math.Pow(4, (2 * rng.NextDouble()) - 1);
            switch (i % 4)
            {
                case 0:
                case 1:
                    pair(a, Polygon(rng, bx, bz, bSize, grid));
                    break;
                case 2:
                    var half = new Vector2((float)(bSize * (0.2 + rng.NextDouble())), (float)(bSize * (0.2 + rng.NextDouble())));
                    var centre = new Vector2((float)bx, (float)bz);
                    pair(grid ? new Aabb(new Vector2((float)bx, (float)bz), new Vector2((float)bx + rng.Next(1, 6), (float)bz + rng.Next(1, 6))) : new Aabb(centre - half, centre + half), a);
                    if (!grid)
                    {
                        pair(KDop8.FromPoints(Polygon(rng, bx, bz, bSize, grid).Vertices), a);
                    }

                    break;
                default:
                    var circle = new Circle(new Vector2((float)bx, (float)bz), (float)(grid ? rng.Next(1, 6) : bSize * (0.3 + rng.NextDouble())));
                    pair(circle, a);
                    pair(a, circle);
                    break;
            }
        }
    }

    // A convex polygon: a regular n-gon (built by repeated exact-input rotation) stretched, turned
    // by a random unit vector and moved; on the grid, an integer rectangle, triangle or diamond.
    private static ConvexPolygon Polygon(Random rng, double cx, double cz, double size, bool grid)
    {
        if (grid)
        {
            int x = (int)cx, z = (int)cz, w = rng.Next(1, 7), h = rng.Next(1, 7);
            return rng.Next(3) switch
            {
                0 => new ConvexPolygon([new(x, z), new(x + w, z), new(x + w, z + h), new(x, z + h)]),
                1 => new ConvexPolygon([new(x, z), new(x + w, z), new(x, z + h)]),
                _ => new ConvexPolygon([new(x, z - h), new(x + w, z), new(x, z + h), new(x - w, z)]),
            };
        }

        int n = rng.Next(10) switch { 0 => 12, 1 => 16, _ => rng.Next(3, 9) };
        var (cos, sin) = Step(n);
        double ux = (2 * rng.NextDouble()) - 1, uz = (2 * rng.NextDouble()) - 1;
        double length = Math.Sqrt((ux * ux) + (uz * uz));
        (ux, uz) = length > 1e-3 ? (ux / length, uz / length) : (1, 0);
        double stretch = 0.3 + (0.7 * rng.NextDouble());
        var v = new Vector2[n];
        double px = 1, pz = 0;
        for (int k = 0; k < n; k++)
        {
            double sx = px * size, sz = pz * size * stretch;
            v[k] = new Vector2((float)(cx + (ux * sx) - (uz * sz)), (float)(cz + (uz * sx) + (ux * sz)));
            (px, pz) = ((px * cos) - (pz * sin), (px * sin) + (pz * cos));
        }

        return new ConvexPolygon(v);
    }

    // cos and sin of 2π/n, written out.
    private static (double Cos, double Sin) Step(int n) => n switch
    {
        3 => (-0.5, 0.8660254037844386),
        4 => (0.0, 1.0),
        5 => (0.30901699437494745, 0.9510565162951535),
        6 => (0.5, 0.8660254037844386),
        7 => (0.6234898018587336, 0.7818314824680298),
        8 => (0.7071067811865476, 0.7071067811865476),
        12 => (0.8660254037844386, 0.5),
        _ => (0.9238795325112867, 0.3826834323650898),
    };

    /// <summary>FNV-1a over the bits of every result.</summary>
    internal sealed class Digest
    {
        public ulong Value { get; private set; } = 14695981039346656037UL;

        public void Add(in CollisionDetectionResult r, bool actionPoint = true)
        {
            Add(r.Intersect ? 1 : 0);
            Add(r.MinimumTranslationVector);
            Add(r.NormalAxis);
            if (actionPoint)
            {
                Add(r.ActionPoint);
            }
        }

        public void Add(Vector3 v)
        {
            Add(BitConverter.SingleToInt32Bits(v.X));
            Add(BitConverter.SingleToInt32Bits(v.Y));
            Add(BitConverter.SingleToInt32Bits(v.Z));
        }

        private void Add(int bits)
        {
            for (int i = 0; i < 4; i++)
            {
                Value = (Value ^ (byte)(bits >> (8 * i))) * 1099511628211UL;
            }
        }
    }
}
