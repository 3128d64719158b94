namespace URWPGSim2D.Server.Tests.Simulation;

/// <summary>The match's body tags: what a body is and its index come back from its tag, and no two bodies share one.</summary>
public sealed class BodyTagTests
{
    [Theory]
    [InlineData(0)]
    [InlineData(1)]
    [InlineData(37)]
    [InlineData(65_535)]
    [InlineData((1 << 24) - 1)]
    public void TheRoleAndIndexComeBackFromTheTag(int index)
    {
        Assert.Equal((BodyRole.Fish, index), (BodyTag.RoleOf(BodyTag.Fish(index)), BodyTag.IndexOf(BodyTag.Fish(index))));
        Assert.Equal((BodyRole.Ball, index), (BodyTag.RoleOf(BodyTag.Ball(index)), BodyTag.IndexOf(BodyTag.Ball(index))));
        Assert.Equal((BodyRole.Static, index), (BodyTag.RoleOf(BodyTag.Static(index)), BodyTag.IndexOf(BodyTag.Static(index))));
        Assert.Equal((BodyRole.Walls, 0), (BodyTag.RoleOf(BodyTag.Walls), BodyTag.IndexOf(BodyTag.Walls)));
        Assert.Equal(BodyRole.None, BodyTag.RoleOf(0));
    }

    [Fact]
    public void NoTwoBodiesOfAMatchShareATag()
    {
        var seen = new System.Collections.Generic.HashSet<int> { BodyTag.Walls };
        for (int i = 0; i < 1000; i++)
        {
            Assert.True(seen.Add(BodyTag.Fish(i)));
            Assert.True(seen.Add(BodyTag.Ball(i)));
            Assert.True(seen.Add(BodyTag.Static(i)));
        }
    }
}
