using System.Drawing;
using XnaFramework = Microsoft.Xna.Framework;

namespace URWPGSim2D.Compat.Tests.Common;

/// <summary>The original's further members of Mission, RoboFish, UrwpgSimHelper, MyMission, RectangularDynamic and Channel.</summary>
[Collection(FieldCollection.Name)]
public sealed class OriginalMembersTests
{
    [Fact]
    public void ReversePoseMirrorsThroughTheCentreAndRecoveryPoseUndoesIt()
    {
        var fish = new RoboFish { PositionMm = new XnaFramework.Vector3(100f, 0f, -50f), BodyDirectionRad = 0.5f };
        fish.ReversePose();
        Assert.Equal(new XnaFramework.Vector3(-100f, 0f, 50f), fish.PositionMm);
        Assert.Equal(0.5f - XnaFramework.MathHelper.Pi, fish.BodyDirectionRad, 5);
        fish.RecoveryPose();
        Assert.Equal(new XnaFramework.Vector3(100f, 0f, -50f), fish.PositionMm);
        Assert.Equal(0.5f, fish.BodyDirectionRad);
    }

    [Fact]
    public void MissionReversePoseTurnsOnlyTheRightHalfTeamsFish()
    {
        var mission = new Mission();
        var left = new Team<RoboFish>();
        left.Fishes.Add(new RoboFish { PositionMm = new XnaFramework.Vector3(10f, 0f, 20f) });
        var right = new Team<RoboFish>();
        right.Para.MyHalfCourt = HalfCourt.RIGHT;
        right.Fishes.Add(new RoboFish { PositionMm = new XnaFramework.Vector3(30f, 0f, 40f), BodyDirectionRad = -1f });
        mission.TeamsRef.Add(left);
        mission.TeamsRef.Add(right);
        mission.ReversePose();
        Assert.Equal(new XnaFramework.Vector3(10f, 0f, 20f), left.Fishes[0].PositionMm);
        Assert.Equal(new XnaFramework.Vector3(-30f, 0f, -40f), right.Fishes[0].PositionMm);
        Assert.Equal(XnaFramework.MathHelper.Pi - 1f, right.Fishes[0].BodyDirectionRad, 5);
        mission.RecoveryPose();
        Assert.Equal(new XnaFramework.Vector3(30f, 0f, 40f), right.Fishes[0].PositionMm);
        Assert.Equal(-1f, right.Fishes[0].BodyDirectionRad);
    }

    [Fact]
    public void CalculateFishPostionPlacesTheOutlineAtTheGivenPose()
    {
        // Reference sizes L 160, W 45, H 30; heading +Z (π/2): forward u = (0, 1), the fish's left n = (sin, −cos) = (1, 0).
        var fish = new RoboFish { PositionMm = new XnaFramework.Vector3(200f, 0f, 100f), BodyDirectionRad = XnaFramework.MathHelper.PiOver2 };
        fish.CalculateFishPostion(true, false, 0f, ref fish);
        AssertClose(new XnaFramework.Vector3(200f, 0f, 100f + 80f + 30f), fish.PolygonVertices[0]); // head tip: L/2 + H ahead
        AssertClose(new XnaFramework.Vector3(222.5f, 0f, 180f), fish.PolygonVertices[1]); // head's left corner
        AssertClose(new XnaFramework.Vector3(177.5f, 0f, 180f), fish.PolygonVertices[6]); // head's right corner
        AssertClose(fish.PolygonVertices[0], fish.BodyPolygonVertices[1]);
        AssertClose(new XnaFramework.Vector3(177.5f, 0f, 20f), fish.BodyPolygonVertices[3]); // rear right
        AssertClose(new XnaFramework.Vector3(222.5f, 0f, 20f), fish.BodyPolygonVertices[4]); // rear left
        // The whole-fish circle (radius (160 + 88 + 66 + 55) / 2 = 184) ends at the head tip.
        AssertClose(new XnaFramework.Vector3(200f, 0f, 210f - 368f), fish.CollisionModelCenterPositionMm);
        AssertClose(new XnaFramework.Vector3(200f, 0f, 210f - 160f), fish.CollisionModelBodyCenterPositionMm);
        // A straight tail lies behind the body: every tail and caudal point is behind the rear edge (Z < 20).
        foreach (var list in new[] { fish.Tail1PolygonVertices, fish.Tail2PolygonVertices, fish.Tail3PolygonVertices, fish.LeftCaudalFinVertices, fish.RightCaudalFinVertices })
        {
            Assert.NotEmpty(list);
            Assert.All(list, p => Assert.True(p.Z <= 20.01f, $"{p} is not behind the body"));
        }

        // The caudal tips are points 3 and 4, left of the axis and right of it (X > 200 is the fish's left here).
        Assert.True(fish.PolygonVertices[3].X > 200f && fish.PolygonVertices[4].X < 200f);
    }

    [Fact]
    public void CalculateFishPostionUsesThePoseOfTheFishPassedAndLeavesItAlone()
    {
        var outline = new RoboFish();
        var posed = new RoboFish { PositionMm = new XnaFramework.Vector3(-300f, 0f, 0f), BodyDirectionRad = XnaFramework.MathHelper.Pi };
        outline.CalculateFishPostion(false, false, 0f, ref posed);
        AssertClose(new XnaFramework.Vector3(-300f - 110f, 0f, 0f), outline.PolygonVertices[0]);
        Assert.Equal(default, posed.PolygonVertices[0]);
        Assert.Equal(new XnaFramework.Vector3(-300f, 0f, 0f), posed.PositionMm);
    }

    [Fact]
    public void SetFishPoseAndSetColorFishChangeOnlyFishInsideTheItemsCounts()
    {
        var mission = new Mission();
        mission.CommonPara.TeamCount = 2;
        mission.CommonPara.FishCntPerTeam = 1;
        for (int t = 0; t < 2; t++)
        {
            var team = new Team<RoboFish>();
            team.Fishes.Add(new RoboFish());
            team.Fishes.Add(new RoboFish()); // beyond FishCntPerTeam
            mission.TeamsRef.Add(team);
        }

        mission.SetFishPose(1, 0, new XnaFramework.Vector3(5f, 0f, 6f), 1.25f);
        Assert.Equal(new XnaFramework.Vector3(5f, 0f, 6f), mission.TeamsRef[1].Fishes[0].PositionMm);
        Assert.Equal(1.25f, mission.TeamsRef[1].Fishes[0].BodyDirectionRad);
        mission.SetFishPose(1, 1, new XnaFramework.Vector3(7f, 0f, 8f), 2f);
        mission.SetFishPose(2, 0, new XnaFramework.Vector3(7f, 0f, 8f), 2f);
        mission.SetFishPose(-1, 0, new XnaFramework.Vector3(7f, 0f, 8f), 2f);
        Assert.Equal(default, mission.TeamsRef[1].Fishes[1].PositionMm);
        Assert.Equal(default, mission.TeamsRef[0].Fishes[0].PositionMm);
        mission.SetColorFish(0, 0, Color.Red);
        mission.SetColorFish(0, 1, Color.Blue);
        Assert.Equal(Color.Red, mission.TeamsRef[0].Fishes[0].ColorFish);
        Assert.Equal(default, mission.TeamsRef[0].Fishes[1].ColorFish);
    }

    [Fact]
    public void SetMissionCommonParaCopiesIntoTheSameObject()
    {
        var mission = new Mission();
        var before = mission.CommonPara;
        var para = new MissionCommonPara("抢球博弈", 2, 3, 300, 100, true, 1) { IsExchangedHalfCourt = true, DisplayingCycles = 4, IsPaused = true, IsRunning = true };
        mission.SetMissionCommonPara(para);
        Assert.Same(before, mission.CommonPara);
        Assert.Equal(("抢球博弈", 2, 3, 300, 100, 3000), (before.Name, before.TeamCount, before.FishCntPerTeam, before.TotalSeconds, before.MsPerCycle, before.RemainingCycles));
        Assert.Equal((true, 1, true, 4, true, true), (before.IsGoalBlockNeeded, before.IsFieldInnerLinesNeeded, before.IsExchangedHalfCourt, before.DisplayingCycles, before.IsPaused, before.IsRunning));
    }

    [Fact]
    public void TheItemHooksLeaveTheMissionAsItWasAndResetColorBallPaintsBallsPink()
    {
        var mission = new Mission();
        var ball = new Ball { PositionMm = new XnaFramework.Vector3(1f, 0f, 2f) };
        mission.EnvRef.Balls.Add(ball);
        var team = new Team<RoboFish>();
        team.Fishes.Add(new RoboFish { PositionMm = new XnaFramework.Vector3(3f, 0f, 4f) });
        mission.TeamsRef.Add(team);
        mission.SetMission();
        mission.ProcessControlRules();
        mission.ResetTeamsAndFishes();
        mission.ResetGoalHandler();
        mission.ResetShootout();
        mission.ResetBalls();
        mission.ResetObstacles();
        mission.ResetDynamicObstacles();
        mission.ResetColorFishAndId();
        mission.ResetEnvironment();
        Assert.Equal(new XnaFramework.Vector3(1f, 0f, 2f), ball.PositionMm);
        Assert.Same(ball, mission.EnvRef.Balls[0]);
        Assert.Equal(new XnaFramework.Vector3(3f, 0f, 4f), mission.TeamsRef[0].Fishes[0].PositionMm);
        Assert.Equal(600, mission.CommonPara.TotalSeconds);
        mission.ResetColorBall();
        Assert.Equal((Color.Pink, Color.Pink), (ball.ColorFilled, ball.ColorBorder));
    }

    [Fact]
    public void ResetFieldPutsTheConfiguredLengthsBack()
    {
        var f = Field.Instance();
        int x = f.FieldLengthXMm, left = f.LeftMm;
        try
        {
            f.FieldLengthXMm = x + 1000;
            new Mission().ResetField();
            Assert.Equal(f.FieldLengthXOriMm, f.FieldLengthXMm);
            Assert.Equal(x, f.FieldLengthXMm);
            Assert.Equal(left, f.LeftMm);
        }
        finally
        {
            f.FieldLengthXMm = x;
            f.FieldCalculation();
        }
    }

    [Fact]
    public void ParametersCheckingMovesABallInsideTheFieldWithoutGoalBlocks()
    {
        // The default field: X −1500..1500, Z −1000..1000. No mission parameters for strategies: no goal blocks.
        var ball = new Ball { PositionMm = new XnaFramework.Vector3(1490f, 0f, 995f) };
        UrwpgSimHelper.ParametersCheckingBall(ref ball);
        Assert.Equal(new XnaFramework.Vector3(1500f - 58f, 0f, 1000f - 58f), ball.PositionMm);
        ball = new Ball(5000) { PositionMm = new XnaFramework.Vector3(0f, 0f, -10f) };
        UrwpgSimHelper.ParametersCheckingBall(ref ball);
        Assert.Equal(1000, ball.RadiusMm);
        Assert.Equal(new XnaFramework.Vector3(0f, 0f, 0f), ball.PositionMm);
        ball = new Ball { PositionMm = new XnaFramework.Vector3(-1480f, 0f, 700f) };
        UrwpgSimHelper.ParametersCheckingBall(ref ball);
        Assert.Equal(new XnaFramework.Vector3(-1500f + 58f, 0f, 700f), ball.PositionMm);
    }

    [Fact]
    public void ParametersCheckingKeepsARoundObstacleOffTheGoalBlocks()
    {
        // Beside the goal band (|Z| ≥ 400) the side wall is a goal depth (150) further in.
        var o = new RoundedObstacle("o", new XnaFramework.Vector3(-1490f, 0f, 500f), Color.Gray, 50);
        UrwpgSimHelper.ParametersCheckingObstacle(ref o);
        Assert.Equal(new XnaFramework.Vector3(-1500f + 150f + 50f, 0f, 500f), o.PositionMm);
        o = new RoundedObstacle("o", new XnaFramework.Vector3(1490f, 0f, 100f), Color.Gray, 50);
        UrwpgSimHelper.ParametersCheckingObstacle(ref o);
        Assert.Equal(new XnaFramework.Vector3(1500f - 50f, 0f, 100f), o.PositionMm);
        o = new RoundedObstacle("o", new XnaFramework.Vector3(0f, 0f, -990f), Color.Gray, 50);
        UrwpgSimHelper.ParametersCheckingObstacle(ref o);
        Assert.Equal(new XnaFramework.Vector3(0f, 0f, -950f), o.PositionMm);
    }

    [Fact]
    public void ParametersCheckingShiftsARectangleByItsOverhang()
    {
        // 200 × 100 along X at X = 1450: corners reach X = 1550, 50 beyond the right wall.
        var r = new RectangularObstacle("r", new XnaFramework.Vector3(1450f, 0f, 0f), Color.Gray, 200, 100, 0f);
        UrwpgSimHelper.ParametersCheckingObstacle(ref r);
        Assert.Equal(new XnaFramework.Vector3(1400f, 0f, 0f), r.PositionMm);
        // Too long for the field: cut to the field's 3000, then moved back by the corners' overhang (−100 − 1500 → −1500).
        r = new RectangularObstacle("r", new XnaFramework.Vector3(-100f, 0f, -980f), Color.Gray, 5000, 100, 0f);
        UrwpgSimHelper.ParametersCheckingObstacle(ref r);
        Assert.Equal(3000, r.LengthMm);
        Assert.Equal(new XnaFramework.Vector3(0f, 0f, -950f), r.PositionMm);
    }

    [Fact]
    public void ParametersCheckingShiftsAFishByItsOutlinesOverhang()
    {
        var fish = new RoboFish { PositionMm = new XnaFramework.Vector3(-1450f, 0f, 990f) };
        fish.PolygonVertices[0] = new XnaFramework.Vector3(-1520.7f, 0f, 990f);
        fish.PolygonVertices[1] = new XnaFramework.Vector3(-1400f, 0f, 1012.5f);
        fish.PolygonVertices[2] = new XnaFramework.Vector3(-1450f, 0f, 1000f);
        fish.PolygonVertices[3] = new XnaFramework.Vector3(-1380f, 0f, 970f);
        UrwpgSimHelper.ParametersCheckingRoboFish(ref fish);
        // Overhangs truncated to whole mm, as the original: X −1520.7 → −1520 (20 left), Z 1012.5 → 1012 (12 below).
        Assert.Equal(new XnaFramework.Vector3(-1430f, 0f, 978f), fish.PositionMm);
    }

    [Fact]
    public void MyMissionIsOneObjectThatTheServerNeverFills()
    {
        var m = MyMission.Instance();
        Assert.Same(m, MyMission.Instance());
        Assert.Null(m.MissionRef);
        Assert.Null(m.ParasRef);
        Assert.Null(m.TeamsRef);
        Assert.Null(m.EnvRef);
        Assert.Null(m.DecisionRef);
        Assert.True(m.IsRomteMode);
    }

    [Fact]
    public void MovingRectangleAndChannelConstructorsAreTheOriginals()
    {
        var d = new RectangularDynamic("d", new XnaFramework.Vector3(100f, 0f, 50f), Color.Red, Color.Blue, 2, 200, 100, 90f, 30f, 0.5f, 0.1f, 40);
        Assert.Equal(("d", 200, 100, 2, true, 40, 40), (d.Name, d.LengthMm, d.WidthMm, d.BorderWidthPix, d.IsDeletionAllowed, d.CircleTimes, d.TimesCouter));
        Assert.Equal(XnaFramework.MathHelper.PiOver2, d.DirectionRad, 6);
        Assert.Equal((30f, 0.5f, 0.1f), (d.VelocityMmPs, d.VelocityDirectionRad, d.AngularVelocityRadPs));
        d.CalculateCollisionDetectionParas();
        // Turned 90°: corner 0 = centre − (L/2)·u + (W/2)·(sin, −cos) = (100 + 50, 50 − 100).
        Assert.Equal(150f, d.PolygonVertices[0].X, 3);
        Assert.Equal(-50f, d.PolygonVertices[0].Z, 3);
        Assert.Equal(111, d.CircumcircleRadiusMm);
        d.SetRectangularDynamic();
        Assert.Equal((100, 100, 0f, 0), (d.LengthMm, d.WidthMm, d.DirectionRad, d.BorderWidthPix));

        var c = new Channel("c", new XnaFramework.Vector3(1f, 0f, 2f), Color.Red, Color.Blue, 300, 80, 180f);
        Assert.Equal(("c", Color.Red, Color.Blue, 300, 80, 0), (c.Name, c.ColorBorder, c.ColorFilled, c.LengthMm, c.WidthMm, c.BorderWidthPix));
        Assert.Equal(XnaFramework.MathHelper.Pi, c.DirectionRad, 6);
        var c2 = new Channel("c2", new XnaFramework.Vector3(1f, 0f, 2f), Color.Red, Color.Blue, 3, 300, 80, -90f);
        Assert.Equal((3, -XnaFramework.MathHelper.PiOver2), (c2.BorderWidthPix, c2.DirectionRad));
    }

    [Fact]
    public void FieldRectanglesScaleToTheDisplayLikeItsPoints()
    {
        var f = Field.Instance();
        var whole = f.MmToPix(f.LeftMm, f.TopMm, f.FieldLengthXMm, f.FieldLengthZMm);
        Assert.Equal((f.MmToPixX(f.LeftMm), f.MmToPixZ(f.TopMm)), (whole.X, whole.Y));
        Assert.Equal((f.FieldLengthXPix, f.FieldLengthZPix), (whole.Width, whole.Height));
        Assert.Equal(whole, f.MmToPix(new Rectangle(f.LeftMm, f.TopMm, f.FieldLengthXMm, f.FieldLengthZMm)));
        Assert.Equal(new Rectangle(f.FieldCenterXPix, f.FieldCenterZPix, 0, 0), f.MmToPix(0, 0, 0, 0));
    }

    private static void AssertClose(XnaFramework.Vector3 expected, XnaFramework.Vector3 actual)
    {
        Assert.Equal(expected.X, actual.X, 3);
        Assert.Equal(expected.Y, actual.Y, 3);
        Assert.Equal(expected.Z, actual.Z, 3);
    }
}
