namespace URWPGSim2D.Common;

/// <summary>The original's checks that move an object back inside the field (<see cref="Field.Instance"/>).</summary>
public static partial class UrwpgSimHelper
{
    /// <summary>
    /// Moves a fish inside the field: if the leftmost of its outline points 0..3 (<see cref="RoboFish.PolygonVertices"/>,
    /// truncated to whole mm) is left of <see cref="Field.LeftMm"/> the fish moves right by the difference, else if the
    /// rightmost is right of <see cref="Field.RightMm"/> it moves left; the same along Z with the top and bottom.
    /// The original redrew the fish first to refresh its outline; here the outline is used as it is (a strategy's copy
    /// has the current one).
    /// </summary>
    /// <param name="obj">The fish; its <see cref="RoboFish.PositionMm"/> changes.</param>
    public static void ParametersCheckingRoboFish(ref RoboFish obj)
    {
        System.ArgumentNullException.ThrowIfNull(obj);
        KeepCornersInside(obj.PolygonVertices, ref obj.PositionMm);
    }

    /// <summary>
    /// Limits a ball's radius to half the field's Z length and moves its centre inside the field, a radius from the
    /// walls; with goal blocks (<see cref="MissionCommonPara.IsGoalBlockNeeded"/> of <see cref="MyMission.ParasRef"/>)
    /// a ball outside −<see cref="Field.GoalWidthMm"/> &lt; Z &lt; <see cref="Field.GoalWidthMm"/> also stays a goal depth
    /// away from the side walls. <see cref="MyMission.ParasRef"/> is never filled for strategies, so here a strategy gets
    /// the check without goal blocks (the original's would have failed on the missing parameters).
    /// </summary>
    /// <param name="obj">The ball; its radius and position may change.</param>
    public static void ParametersCheckingBall(ref Ball obj)
    {
        System.ArgumentNullException.ThrowIfNull(obj);
        bool goalBlocks = MyMission.Instance().ParasRef?.IsGoalBlockNeeded ?? false;
        int radius = obj.RadiusMm;
        KeepRoundInside(ref obj.PositionMm, ref radius, goalBlocks);
        obj.RadiusMm = radius;
    }

    /// <summary>
    /// Limits a rectangular obstacle's length and width to the field's, recomputes its corners
    /// (<see cref="RectangularStatic.CalculateCollisionDetectionParas"/>) and moves it inside the field as
    /// <see cref="ParametersCheckingRoboFish"/> does with the four corners.
    /// </summary>
    /// <param name="obj">The obstacle; its size, corners and position may change.</param>
    public static void ParametersCheckingObstacle(ref RectangularObstacle obj)
    {
        System.ArgumentNullException.ThrowIfNull(obj);
        var f = Field.Instance();
        obj.LengthMm = obj.LengthMm > f.FieldLengthXMm ? f.FieldLengthXMm : obj.LengthMm;
        obj.WidthMm = obj.WidthMm > f.FieldLengthZMm ? f.FieldLengthZMm : obj.WidthMm;
        obj.CalculateCollisionDetectionParas();
        KeepCornersInside(obj.PolygonVertices, ref obj.PositionMm);
    }

    /// <summary>
    /// Limits a round obstacle's radius to half the field's Z length and moves its centre inside the field, a radius
    /// from the walls, and outside −<see cref="Field.GoalWidthMm"/> &lt; Z &lt; <see cref="Field.GoalWidthMm"/> also a goal
    /// depth away from the side walls (always, as in the original).
    /// </summary>
    /// <param name="obj">The obstacle; its radius and position may change.</param>
    public static void ParametersCheckingObstacle(ref RoundedObstacle obj)
    {
        System.ArgumentNullException.ThrowIfNull(obj);
        int radius = obj.RadiusMm;
        KeepRoundInside(ref obj.PositionMm, ref radius, goalBlocks: true);
        obj.RadiusMm = radius;
    }

    // Moves position so that the outline points 0..3 (truncated to whole mm) lie inside the field, along X and along Z.
    private static void KeepCornersInside(List<Microsoft.Xna.Framework.Vector3> v, ref Microsoft.Xna.Framework.Vector3 position)
    {
        var f = Field.Instance();
        int dx = Inward(v[0].X, v[1].X, v[2].X, v[3].X, f.LeftMm, f.RightMm);
        int dz = Inward(v[0].Z, v[1].Z, v[2].Z, v[3].Z, f.TopMm, f.BottomMm);
        if (dx != 0)
        {
            position.X += dx;
        }

        if (dz != 0)
        {
            position.Z += dz;
        }
    }

    // How far the four values (truncated) move to lie within low..high: up by what the least lies below low, else
    // down by what the greatest lies above high, else 0.
    private static int Inward(float a, float b, float c, float d, int low, int high)
    {
        int seq = 0;
        int min = (int)Min(a, b, c, d, ref seq);
        if (min < low)
        {
            return low - min;
        }

        int max = (int)Max(a, b, c, d, ref seq);
        return max > high ? high - max : 0;
    }

    private static void KeepRoundInside(ref Microsoft.Xna.Framework.Vector3 position, ref int radius, bool goalBlocks)
    {
        var f = Field.Instance();
        radius = radius > f.FieldLengthZMm / 2 ? f.FieldLengthZMm / 2 : radius;
        if (position.Z < f.TopMm + radius)
        {
            position.Z = f.TopMm + radius;
        }
        else if (position.Z > f.BottomMm - radius)
        {
            position.Z = f.BottomMm - radius;
        }

        // Beside the goals (outside the band between them) the goal blocks push the side walls in by a goal depth.
        int side = goalBlocks && !(position.Z > -f.GoalWidthMm && position.Z < f.GoalWidthMm) ? f.GoalDepthMm : 0;
        if (position.X < f.LeftMm + side + radius)
        {
            position.X = f.LeftMm + side + radius;
        }
        else if (position.X > f.RightMm - side - radius)
        {
            position.X = f.RightMm - side - radius;
        }
    }
}
