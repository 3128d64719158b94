namespace URWPGSim2D.Collision.Tests.BroadPhase;

/// <summary>
/// The tree's walks for queries (<see cref="DynamicAabbTree.Segment"/>, <see cref="DynamicAabbTree.Near"/>)
/// and appended proxies, on random worlds of boxes (points, flat, huge, duplicate and touching
/// boxes among them) after moves: no box a segment passes through is left out (points sampled
/// along it), and the walk toward a point finds the nearest box brute force finds.
/// </summary>
public sealed class DynamicAabbTreeWalkTests
{
    [Theory]
    [InlineData(1)]
    [InlineData(2)]
    public void SegmentsVisitEveryBoxTheyPassThrough(int seed)
    {
        var (tree, world, boxes) = Build(seed);
        for (int q = 0; q < 200; q++)
        {
            Vector2 from = world.Box(3000f).Center, to = q % 10 == 0 ? from : world.Box(3000f).Center;
            var visitor = new Collect(1f);
            tree.Segment(from, to, 1f, ref visitor);
            Assert.Equal(visitor.Visited.Count, visitor.Visited.Distinct().Count());
            for (int k = 0; k <= 200; k++)
            {
                Vector2 p = Vector2.Lerp(from, to, k / 200f);
                for (int b = 0; b < boxes.Count; b++)
                {
                    if (Inside(p, boxes[b]))
                    {
                        Assert.True(visitor.Visited.Contains(b), $"segment {q} from {from} to {to}: box {b} {boxes[b]} holds {p} but was not visited");
                    }
                }
            }

            // A bound of 0 keeps only the boxes at the start.
            var start = new Collect(0f);
            tree.Segment(from, to, 0f, ref start);
            for (int b = 0; b < boxes.Count; b++)
            {
                Assert.True(!Inside(from, boxes[b]) || start.Visited.Contains(b), $"segment {q}: box {b} holds the start but was not visited");
            }
        }
    }

    [Theory]
    [InlineData(3)]
    [InlineData(4)]
    public void TheWalkTowardAPointFindsTheNearestBox(int seed)
    {
        var (tree, world, boxes) = Build(seed);
        for (int q = 0; q < 300; q++)
        {
            Vector2 point = world.Box(4000f).Center;
            var nearest = new NearestBox(point, boxes);
            tree.Near(point, float.PositiveInfinity, ref nearest);
            float least = boxes.Min(b => Vector2.Distance(point, Vector2.Clamp(point, b.Min, b.Max)));
            Assert.Equal(least, nearest.Distance);
            Assert.True(nearest.Visits < boxes.Count / 4, $"point {q}: {nearest.Visits} of {boxes.Count} boxes visited");

            var all = new Collect(float.PositiveInfinity);
            tree.Near(point, float.PositiveInfinity, ref all);
            Assert.Equal(boxes.Count, all.Visited.Distinct().Count());
        }
    }

    [Fact]
    public void ClearingEmptiesTheTree()
    {
        var (tree, _, _) = Build(5);
        tree.Clear();
        Assert.Equal(0, tree.Count);
        Assert.Equal(-1, tree.Height);
        var visitor = new Collect(float.PositiveInfinity);
        tree.Near(Vector2.Zero, float.PositiveInfinity, ref visitor);
        tree.Segment(new Vector2(-1e4f), new Vector2(1e4f), 1f, ref visitor);
        Assert.Empty(visitor.Visited);
        Assert.Equal(0, tree.Append(new Aabb(Vector2.Zero, Vector2.One)));
        tree.Near(Vector2.Zero, float.PositiveInfinity, ref visitor);
        Assert.Equal(new[] { 0 }, visitor.Visited);
    }

    // 1,000 boxes given at once, 1,000 appended, then 5,000 moves; the boxes as the tree holds them.
    private static (DynamicAabbTree Tree, RandomBoxWorld World, List<Aabb> Boxes) Build(int seed)
    {
        var tree = new DynamicAabbTree();
        var world = new RandomBoxWorld(seed);
        var boxes = world.Boxes(1000, 3000f).ToList();
        tree.Reset(boxes.ToArray(), 0);
        foreach (Aabb box in world.Boxes(1000, 3000f))
        {
            Assert.Equal(boxes.Count, tree.Append(box));
            boxes.Add(box);
        }

        for (int i = 0; i < 5000; i++)
        {
            int p = world.Random.Next(boxes.Count);
            boxes[p] = world.Box(3000f);
            tree.Move(p, boxes[p]);
        }

        Assert.Equal(boxes.Count, tree.Count);
        Assert.InRange(tree.Height, 11, 2 * 11);
        return (tree, world, boxes);
    }

    private static bool Inside(Vector2 p, in Aabb box) => p.X >= box.Min.X && p.X <= box.Max.X && p.Y >= box.Min.Y && p.Y <= box.Max.Y;

    private struct Collect(float bound) : IProxyVisitor
    {
        public List<int> Visited { get; } = [];

        public readonly float Visit(int proxy)
        {
            Visited.Add(proxy);
            return bound;
        }
    }

    private struct NearestBox(Vector2 point, List<Aabb> boxes) : IProxyVisitor
    {
        public float Distance { get; private set; } = float.PositiveInfinity;

        public int Visits { get; private set; }

        public float Visit(int proxy)
        {
            Visits++;
            Aabb b = boxes[proxy];
            Distance = MathF.Min(Distance, Vector2.Distance(point, Vector2.Clamp(point, b.Min, b.Max)));
            return Distance;
        }
    }
}
