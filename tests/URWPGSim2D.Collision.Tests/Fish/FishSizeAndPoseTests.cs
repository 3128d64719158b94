namespace URWPGSim2D.Collision.Tests.Fish;

public class FishSizeAndPoseTests
{
    [Fact]
    public void DefaultIsTheDeployedConfiguration()
    {
        var s = FishSize.Default;
        Assert.Equal((160f, 45f, 30f, 88f, 66f, 55f), (s.Length, s.Width, s.Head, s.Joint1, s.Joint2, s.Joint3));
    }

    [Theory]
    [InlineData(0, 0f)]
    [InlineData(1, -1f)]
    [InlineData(2, float.NaN)]
    [InlineData(3, float.PositiveInfinity)]
    [InlineData(4, 0f)]
    [InlineData(5, -0.5f)]
    public void BadSizeValueIsNamed(int which, float bad)
    {
        string[] names = ["length", "width", "head", "joint1", "joint2", "joint3"];
        float[] v = [160f, 45f, 30f, 88f, 66f, 55f];
        v[which] = bad;
        var e = Assert.Throws<ArgumentException>(() => new FishSize(v[0], v[1], v[2], v[3], v[4], v[5]));
        Assert.Equal(names[which], e.ParamName);
        Assert.Contains(bad.ToString(System.Globalization.CultureInfo.InvariantCulture), e.Message, StringComparison.Ordinal);
    }

    [Fact]
    public void JointThreeThatFlattensTheLeftCaudalFinIsRejected()
    {
        // Left caudal (−2L3, −50), (−1.8L3, −10), (−L3, 0.089964·L3) is collinear when 0.2·0.089964·L3 = 30.
        float flat = 30f / (0.2f * 0.089964f);
        var e = Assert.Throws<ArgumentException>(() => new FishSize(160f, 45f, 30f, 88f, 66f, flat));
        Assert.Equal("joint3", e.ParamName);
        Assert.Contains("LeftCaudal", e.Message, StringComparison.Ordinal);
    }

    [Fact]
    public void LargeJointThreeFlipsTheCaudalWindingButLeavesAreStillCounterClockwise()
    {
        var size = new FishSize(160f, 45f, 30f, 88f, 66f, 3000f);
        var fish = new FishModel(size, new FishPose(new Vector2(10f, 20f), 1f, 0.2f, -0.3f, 0.4f));
        foreach (var part in FishTestKit.AllParts)
        {
            Assert.True(ConvexPolygon.SignedArea2(fish.GetLeaf(part)) > 0f, part.ToString());
        }
    }

    [Theory]
    [InlineData(0, "position")]
    [InlineData(1, "heading")]
    [InlineData(2, "joint1")]
    [InlineData(3, "joint2")]
    [InlineData(4, "joint3")]
    public void NonFinitePoseValueIsNamed(int which, string name)
    {
        float[] v = [0f, 0f, 0f, 0f, 0f];
        v[which] = float.NaN;
        var e = Assert.Throws<ArgumentException>(() => new FishPose(new Vector2(v[0], 0f), v[1], v[2], v[3], v[4]));
        Assert.Equal(name, e.ParamName);
        Assert.Contains("NaN", e.Message, StringComparison.Ordinal);
    }

    [Fact]
    public void PoseKeepsItsValuesAndTranslates()
    {
        var pose = new FishPose(new Vector2(1f, 2f), 3f, 0.1f, 0.2f, 0.3f);
        Assert.Equal((new Vector2(1f, 2f), 3f, 0.1f, 0.2f, 0.3f), (pose.Position, pose.Heading, pose.Joint1, pose.Joint2, pose.Joint3));
        var moved = pose.Translated(new Vector2(10f, -5f));
        Assert.Equal(new FishPose(new Vector2(11f, -3f), 3f, 0.1f, 0.2f, 0.3f), moved);
        var fish = new FishModel(FishSize.Default, pose);
        Assert.Equal(pose, fish.Pose);
        Assert.Equal(FishSize.Default, fish.Size);
    }

    [Fact]
    public void HeadTipAndForwardFollowTheHeading()
    {
        var fish = new FishModel(FishSize.Default, new FishPose(new Vector2(100f, 50f), MathF.PI / 2f, 0f, 0f, 0f));
        Assert.Equal(0f, fish.Forward.X, 1e-6f);
        Assert.Equal(1f, fish.Forward.Y, 1e-6f);
        Assert.Equal(100f, fish.HeadTip.X, 1e-3f);
        Assert.Equal(160f, fish.HeadTip.Y, 1e-3f);
        Assert.Contains(fish.GetLeaf(FishPart.Body).ToArray(), v => Vector2.Distance(v, fish.HeadTip) < 1e-3f);
    }
}
