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
        Outline(position, heading, BodyLength, BodyWidth, HeadLength, model);
    }

    // Fills the vertex lists from the fish model (posed at position, heading): the body in the original's order, the
    // other leaves as the model holds them (a mission's fish, and CalculateFishPostion).
    internal void Outline(Vector2 position, float heading, float bodyLength, float width, float headLength, FishModel model)
    {
        var (sin, cos) = MathF.SinCos(heading);
        Vector2 u = new(cos, sin), left = new(sin, -cos);
        float hl = 0.5f * bodyLength, hw = 0.5f * width;
        Vector2 p = position;
        Vector2 headLeft = p + (u * hl) + (left * hw), headRight = p + (u * hl) - (left * hw);
        Vector2 tip = p + (u * (hl + headLength));
        BodyPolygonVertices[0] = Xna.Vector3.FromXZ(headLeft);
        BodyPolygonVertices[1] = Xna.Vector3.FromXZ(tip);
        BodyPolygonVertices[2] = Xna.Vector3.FromXZ(headRight);
        BodyPolygonVertices[3] = Xna.Vector3.FromXZ(p - (u * hl) - (left * hw));
        BodyPolygonVertices[4] = Xna.Vector3.FromXZ(p - (u * hl) + (left * hw));
        Leaf(LeftPectoralPolygonVertices, model.GetLeaf(FishPart.LeftPectoral));
        Leaf(RightPectoralPolygonVertices, model.GetLeaf(FishPart.RightPectoral));
        Leaf(Tail1PolygonVertices, model.GetLeaf(FishPart.Tail1));
        Leaf(Tail2PolygonVertices, model.GetLeaf(FishPart.Tail2));
        Leaf(Tail3PolygonVertices, model.GetLeaf(FishPart.Tail3));
        Leaf(LeftCaudalFinVertices, model.GetLeaf(FishPart.LeftCaudal));
        Leaf(RightCaudalFinVertices, model.GetLeaf(FishPart.RightCaudal));

        PolygonVertices[0] = Xna.Vector3.FromXZ(tip);
        PolygonVertices[1] = Xna.Vector3.FromXZ(headLeft);
        PolygonVertices[2] = Xna.Vector3.FromXZ(Farthest(model.GetLeaf(FishPart.LeftPectoral), p));
        PolygonVertices[3] = Xna.Vector3.FromXZ(Farthest(model.GetLeaf(FishPart.LeftCaudal), p));
        PolygonVertices[4] = Xna.Vector3.FromXZ(Farthest(model.GetLeaf(FishPart.RightCaudal), p));
        PolygonVertices[5] = Xna.Vector3.FromXZ(Farthest(model.GetLeaf(FishPart.RightPectoral), p));
        PolygonVertices[6] = Xna.Vector3.FromXZ(headRight);

        CollisionModelCenterPositionMm = Xna.Vector3.FromXZ(tip - (u * (2f * CollisionModelRadiusMm)));
        CollisionModelBodyCenterPositionMm = Xna.Vector3.FromXZ(tip - (u * (2f * CollisionModelBodyRadiusMm)));
        CollisionModelTailCenterPositionMm = Xna.Vector3.FromXZ(model.TailGroup.Center);
    }

    private static void Leaf(List<Xna.Vector3> into, ReadOnlySpan<Vector2> points)
    {
        into.Clear();
        foreach (var q in points)
        {
            into.Add(Xna.Vector3.FromXZ(q));
        }
    }

    private static Vector2 Farthest(ReadOnlySpan<Vector2> points, Vector2 from)
    {
        Vector2 best = points[0];
        float bestD = -1f;
        foreach (var q in points)
        {
            float d = Vector2.DistanceSquared(q, from);
            if (d > bestD)
            {
                bestD = d;
                best = q;
            }
        }

        return best;
    }
}
