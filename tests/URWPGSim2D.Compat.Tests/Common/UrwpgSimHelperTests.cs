using XnaFramework = Microsoft.Xna.Framework;

namespace URWPGSim2D.Compat.Tests.Common;

/// <summary>The original's small helpers and data types.</summary>
[Collection(FieldCollection.Name)]
public sealed class UrwpgSimHelperTests
{
    [Fact]
    public void ExtremesReportTheFirstIndex()
    {
        int seq = -1;
        Assert.Equal(5, UrwpgSimHelper.Max(1, 5, 5, 2, ref seq));
        Assert.Equal(1, seq);
        Assert.Equal(1f, UrwpgSimHelper.Min(4f, 1f, 3f, 1f, ref seq));
        Assert.Equal(1, seq);
        Assert.Equal(9f, UrwpgSimHelper.Max(1f, 2f, 3f, 4f, 5f, 6f, 9f, ref seq));
        Assert.Equal(6, seq);
        Assert.Equal(-2f, UrwpgSimHelper.Min(0f, 1f, 2f, 3f, -2f, ref seq));
        Assert.Equal(4, seq);
    }

    [Fact]
    public void FrameTransformationsRotateAndTranslate()
    {
        // Local X axis pointing +Z (θ = π/2) at (100, 200): local (10, 0) is world (100, 210), local (0, 10) is world (90, 200).
        var origin = new XnaFramework.Vector3(100f, 0f, 200f);
        var world = default(XnaFramework.Vector3);
        UrwpgSimHelper.CoordinateTransformation(XnaFramework.MathHelper.PiOver2, origin, new XnaFramework.Vector3(10f, 0f, 0f), ref world);
        Assert.Equal(100f, world.X, 4);
        Assert.Equal(210f, world.Z, 4);
        UrwpgSimHelper.CoordinateTransformation(XnaFramework.MathHelper.PiOver2, origin, new XnaFramework.Vector3(0f, 0f, 10f), ref world);
        Assert.Equal(90f, world.X, 4);
        Assert.Equal(200f, world.Z, 4);

        var local = default(XnaFramework.Vector3);
        UrwpgSimHelper.CoordinateTransformation(XnaFramework.MathHelper.PiOver2, origin, ref local, new XnaFramework.Vector3(90f, 0f, 200f));
        Assert.Equal(0f, local.X, 4);
        Assert.Equal(10f, local.Z, 4);
    }

    [Fact]
    public void DefaultsAreTheOriginals()
    {
        var mission = new Mission();
        Assert.Equal(100, mission.CommonPara.MsPerCycle);
        Assert.Equal(6000, mission.CommonPara.RemainingCycles);
        var fish = new RoboFish();
        Assert.Equal(7, fish.PolygonVertices.Count);
        Assert.Equal(7, fish.Tactic.TCode);
        Assert.Equal((160 + 88 + 66 + 55) / 2, fish.CollisionModelRadiusMm);
        Assert.Equal(58, new Ball().RadiusMm);
        var f = Field.Instance();
        Assert.Same(f, Field.Instance());
        Assert.Equal((-1500, 1500, -1000, 1000), (f.LeftMm, f.RightMm, f.TopMm, f.BottomMm));
        Assert.Equal((400, 150, 400, 1000), (f.GoalWidthMm, f.GoalDepthMm, f.ForbiddenZoneLengthXMm, f.ForbiddenZoneLengthZMm));
        Assert.Equal(0, (int)HalfCourt.LEFT);
        Assert.Equal(8, (int)CollisionType.BALL_CHANNEL);
    }

    [Fact]
    public void RectangleCornersFollowTheDirection()
    {
        var r = new RectangularObstacle("r", new XnaFramework.Vector3(100f, 0f, 50f), System.Drawing.Color.Gray, 200, 100, 90f);
        // Turned 90°: the 200 mm length runs along Z. Corner 0 = centre − (L/2)·u + (W/2)·(sin, −cos) = (100 + 50, 50 − 100).
        Assert.Equal(150f, r.PolygonVertices[0].X, 3);
        Assert.Equal(-50f, r.PolygonVertices[0].Z, 3);
        Assert.Equal(111, r.CircumcircleRadiusMm); // √(200² + 100²) = 223.6 → 223 / 2
        var copy = (RectangularObstacle)r.Clone();
        Assert.Equal("r", copy.Name);
        Assert.Equal(0f, copy.PolygonVertices[0].X); // corners are not copied for strategies
    }
}
