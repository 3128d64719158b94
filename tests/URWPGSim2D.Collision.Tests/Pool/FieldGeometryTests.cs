namespace URWPGSim2D.Collision.Tests.Pool;

public class FieldGeometryTests
{
    [Fact]
    public void DefaultFieldIsThreeByTwoMetres()
    {
        var field = new Field();
        Assert.Equal(3000f, field.Length);
        Assert.Equal(2000f, field.Width);
        Assert.Equal(new Vector2(-1500f, -1000f), field.Bounds.Min);
        Assert.Equal(new Vector2(1500f, 1000f), field.Bounds.Max);
        Assert.Equal(400f, Field.GoalWidth);
        Assert.Equal(150f, Field.GoalDepth);
    }

    [Fact]
    public void GoalBlocksAreTheExactCornerBoxesInGoalBlockOrder()
    {
        var blocks = new Field().GoalBlocks;
        Assert.Equal(4, blocks.Length);

        // goalBlock1 left top, 2 right top, 3 left bottom, 4 right bottom; inner faces at |x| = 1350 exactly.
        AssertBox(blocks[0], -1500f, -1350f, -1000f, -200f);
        AssertBox(blocks[1], 1350f, 1500f, -1000f, -200f);
        AssertBox(blocks[2], -1500f, -1350f, 200f, 1000f);
        AssertBox(blocks[3], 1350f, 1500f, 200f, 1000f);
    }

    [Fact]
    public void LargeFieldMovesTheBlocksWithTheEdges()
    {
        var field = new Field(4500f, 3000f);
        var blocks = field.GoalBlocks;
        AssertBox(blocks[0], -2250f, -2100f, -1500f, -200f);
        AssertBox(blocks[3], 2100f, 2250f, 200f, 1500f);
        Assert.Equal(new Vector2(2250f, 1500f), field.Bounds.Max);
    }

    [Fact]
    public void OuterCirclesPassThroughTheBlockCorners()
    {
        var field = new Field();
        Assert.Equal(4, field.GoalBlockOuterCircles.Length);
        for (int i = 0; i < 4; i++)
        {
            var box = field.GoalBlocks[i];
            var circle = field.GoalBlockOuterCircles[i];
            Assert.Equal((box.Min + box.Max) / 2f, circle.Center);
            Assert.Equal(MathF.Sqrt((75f * 75f) + (400f * 400f)), circle.Radius, 1e-3f);
            foreach (var corner in new[] { box.Min, box.Max, new Vector2(box.Min.X, box.Max.Y), new Vector2(box.Max.X, box.Min.Y) })
            {
                Assert.Equal(circle.Radius, Vector2.Distance(corner, circle.Center), 1e-3f);
            }
        }
    }

    [Fact]
    public void WithoutGoalBlocksThereAreNone()
    {
        var field = new Field(goalBlocks: false);
        Assert.Equal(0, field.GoalBlocks.Length);
        Assert.Equal(0, field.GoalBlockOuterCircles.Length);
        Assert.Equal(4, field.Walls.Length);
    }

    [Fact]
    public void WallsAreTheFourEdgesTopRightBottomLeft()
    {
        var walls = new Field().Walls;
        Assert.Equal(4, walls.Length);
        AssertSegment(walls[0], new(-1500f, -1000f), new(1500f, -1000f));
        AssertSegment(walls[1], new(1500f, -1000f), new(1500f, 1000f));
        AssertSegment(walls[2], new(1500f, 1000f), new(-1500f, 1000f));
        AssertSegment(walls[3], new(-1500f, 1000f), new(-1500f, -1000f));
    }

    [Theory]
    [InlineData(float.NaN, 2000f, "length")]
    [InlineData(0f, 2000f, "length")]
    [InlineData(300f, 2000f, "length")]
    [InlineData(3000f, -1f, "width")]
    [InlineData(3000f, 400f, "width")]
    [InlineData(3000f, float.PositiveInfinity, "width")]
    public void BadSizesAreNamed(float length, float width, string name)
    {
        var e = Assert.Throws<ArgumentException>(() => new Field(length, width));
        Assert.Equal(name, e.ParamName);
        float bad = name == "length" ? length : width;
        Assert.Contains(bad.ToString(System.Globalization.CultureInfo.InvariantCulture), e.Message, StringComparison.Ordinal);
    }

    private static void AssertBox(Aabb box, float minX, float maxX, float minZ, float maxZ)
    {
        Assert.Equal(new Vector2(minX, minZ), box.Min);
        Assert.Equal(new Vector2(maxX, maxZ), box.Max);
    }

    private static void AssertSegment(Segment s, Vector2 a, Vector2 b)
    {
        Assert.Equal(a, s.A);
        Assert.Equal(b, s.B);
    }
}
