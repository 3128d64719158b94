using System.Numerics;
using URWPGSim2D.Collision.Fish;
using Xna = Microsoft.Xna.Framework;

namespace URWPGSim2D.Common;

/// <summary>The original's pose helpers of <see cref="RoboFish"/>.</summary>
public partial class RoboFish
{
    private Xna.Vector3 _savedPositionMm;
    private float _savedBodyDirectionRad;

    /// <summary>
    /// Mirrors the pose through the field centre: remembers <see cref="PositionMm"/> and <see cref="BodyDirectionRad"/>,
    /// then negates the position and turns the body by π (wrapped to (−π, π]). <see cref="RecoveryPose"/> restores
    /// what was remembered. The server gives strategies absolute coordinates; this only changes the object it is called on.
    /// </summary>
    public void ReversePose()
    {
        _savedPositionMm = PositionMm;
        PositionMm = -PositionMm;
        _savedBodyDirectionRad = BodyDirectionRad;
        BodyDirectionRad = Xna.MathHelper.WrapAngle(BodyDirectionRad + Xna.MathHelper.Pi);
    }

    /// <summary>Restores the position and body direction the last <see cref="ReversePose"/> remembered (zero if it was never called).</summary>
    public void RecoveryPose()
    {
        PositionMm = _savedPositionMm;
        BodyDirectionRad = _savedBodyDirectionRad;
    }

    /// <summary>
    /// Recomputes this fish's outline (<see cref="PolygonVertices"/>, <see cref="BodyPolygonVertices"/>, the fin and tail
    /// polygons, the collision circles' centres) for the pose of <paramref name="fish"/> (<see cref="PositionMm"/>,
    /// <see cref="BodyDirectionRad"/>) with this fish's sizes and tail angles, by the same model that fills the outline
    /// the server gives strategies. Usually called on a fish with itself, <c>f.CalculateFishPostion(…, ref f)</c>, after
    /// moving it. <paramref name="isRunning"/>, <paramref name="isPaused"/> and <paramref name="initPhase"/> are unused,
    /// as in the original.
    /// </summary>
    /// <param name="isRunning">Unused.</param>
    /// <param name="isPaused">Unused.</param>
    /// <param name="initPhase">Unused.</param>
    /// <param name="fish">The fish whose pose to use (not changed).</param>
    public void CalculateFishPostion(bool isRunning, bool isPaused, float initPhase, ref RoboFish fish)
    {
        System.ArgumentNullException.ThrowIfNull(fish);
        var position = new Vector2(fish.PositionMm.X, fish.PositionMm.Z);
        float heading = fish.BodyDirectionRad;
        var size = new FishSize(BodyLength, BodyWidth, HeadLength, TailJointLength1, TailJointLength2, TailJointLength3);
        var model = new FishModel(size, new FishPose(position, heading, TailToBodyAngle1, TailToBodyAngle2, TailToBodyAngle3));
        URWPGSim2D.Compat.Adapter.MissionBuilder.Outline(this, position, heading, BodyLength, BodyWidth, HeadLength, model);
    }
}
