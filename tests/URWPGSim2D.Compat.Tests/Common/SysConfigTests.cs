namespace URWPGSim2D.Compat.Tests.Common;

/// <summary>The original's configuration reader serves the deployed configuration.</summary>
public sealed class SysConfigTests
{
    [Fact]
    public void ReadsTheDeployedValuesByNameAndByPath()
    {
        var config = SysConfig.Instance();
        Assert.Equal("160", config.MyXmlReader("BodyLength"));
        Assert.Equal("45", config.MyXmlReader("BodyWidth"));
        Assert.Equal(("88", "66", "55"), (config.MyXmlReader("TailJointLength1"), config.MyXmlReader("TailJointLength2"), config.MyXmlReader("TailJointLength3")));
        Assert.Equal("58", config.MyXmlReader("BallRadius"));
        Assert.Equal("1000", config.MyXmlReader("ForbiddenZoneLengthZMm"));
        // By name the first element in document order answers: the first moving obstacle's direction.
        Assert.Equal("-1.5707963267949", config.MyXmlReader("VelocityDirectionRad"));
        Assert.Equal("1.5707963267949", config.GetValue("/config/missions/newmatch2v2/dynamicRectangle2/VelocityDirectionRad"));
        Assert.Equal("3000", config.GetValue("/config/field/FieldLengthXMm"));
        Assert.Equal(160, Convert.ToInt32(config.MyXmlReader("BodyLength"), System.Globalization.CultureInfo.InvariantCulture));
        Assert.Throws<InvalidOperationException>(() => config.MyXmlReader("NoSuchKey"));
        Assert.Throws<InvalidOperationException>(() => config.GetValue("/config/nothing"));
    }

    [Fact]
    public void OneReaderUntilReleased()
    {
        var first = SysConfig.Instance();
        Assert.Same(first, SysConfig.Instance());
        SysConfig.release();
        var second = SysConfig.Instance();
        Assert.NotSame(first, second);
        Assert.Equal("58", second.MyXmlReader("BallRadius"));
    }
}
