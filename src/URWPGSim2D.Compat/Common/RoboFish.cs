using System.Collections;
using Xna = Microsoft.Xna.Framework;

namespace URWPGSim2D.Common;

/// <summary>
/// A fish as the original's strategies see it (mm, mm/s, rad, rad/s; absolute field coordinates).
/// The server fills the pose, speeds, sizes, tail angles and the polygon vertices; the
/// <c>Pre*</c> fields, the decisions (<see cref="Tactic"/> …) and the colours arrive at their defaults,
/// as in the original's copy for strategies.
/// </summary>
[Serializable]
public partial class RoboFish : ICloneable
{
    /// <summary>Creates a fish of the reference size at the origin, heading +X.</summary>
    public RoboFish()
    {
        for (int i = 0; i < 4; i++)
        {
            Tail1PolygonVertices.Add(default);
            Tail2PolygonVertices.Add(default);
            Tail3PolygonVertices.Add(default);
            LeftPectoralPolygonVertices.Add(default);
            RightPectoralPolygonVertices.Add(default);
            TransactionVectorThreshold.Add(0f);
        }

        for (int i = 0; i < 5; i++)
        {
            BodyPolygonVertices.Add(default);
        }

        for (int i = 0; i < 7; i++)
        {
            PolygonVertices.Add(default);
            PrePolygonVertices.Add(default);
        }

        for (int i = 0; i < 3; i++)
        {
            LeftCaudalFinVertices.Add(default);
            RightCaudalFinVertices.Add(default);
        }

        Tactic.TCode = 7;
        PreTactic.TCode = 7;
        TargetTactic.TCode = 7;
        SetFish();
    }

    /// <summary>Per-fish values an item passes to strategies (string keys and values).</summary>
    public Hashtable HtFishVariables = new();

    /// <summary>Head length, mm (30).</summary>
    public int HeadLength;

    /// <summary>Body length, mm (160).</summary>
    public int BodyLength;

    /// <summary>Body width, mm (45).</summary>
    public int BodyWidth;

    /// <summary>Tail segment 1 length, mm.</summary>
    public int TailJointLength1;

    /// <summary>Tail segment 2 length, mm.</summary>
    public int TailJointLength2;

    /// <summary>Tail segment 3 length, mm.</summary>
    public int TailJointLength3;

    /// <summary>Angle of tail joint 1 from the body axis, rad.</summary>
    public float TailToBodyAngle1;

    /// <summary>Angle of tail joint 2 from the body axis, rad.</summary>
    public float TailToBodyAngle2;

    /// <summary>Angle of tail joint 3 from the body axis, rad.</summary>
    public float TailToBodyAngle3;

    /// <summary>Initial phase of the tail wave.</summary>
    public float InitPhase;

    /// <summary>Centre of the body rectangle, mm (Y = 0).</summary>
    public Xna.Vector3 PositionMm;

    /// <summary>Last cycle's position (not given to strategies: zero).</summary>
    public Xna.Vector3 PrePositionMm;

    /// <summary>Body direction, rad in (−π, π], from +X toward +Z.</summary>
    public float BodyDirectionRad;

    /// <summary>Last cycle's body direction (not given to strategies: zero).</summary>
    public float PreBodyDirectionRad;

    /// <summary>Speed, mm/s.</summary>
    public float VelocityMmPs;

    /// <summary>Last cycle's speed (not given to strategies: zero).</summary>
    public float PreVelocityMmPs;

    /// <summary>Direction of the velocity, rad (the body direction).</summary>
    public float VelocityDirectionRad;

    /// <summary>Last cycle's velocity direction (not given to strategies: zero).</summary>
    public float PreVelocityDirectionRad;

    /// <summary>Angular speed, rad/s (positive turns toward +Z, clockwise on screen).</summary>
    public float AngularVelocityRadPs;

    /// <summary>Last cycle's angular speed (not given to strategies: zero).</summary>
    public float PreAngularVelocityRadPs;

    /// <summary>The decision being executed (not given to strategies: VCode 0, TCode 7).</summary>
    public Decision Tactic;

    /// <summary>The previous decision (not given to strategies).</summary>
    public Decision PreTactic;

    /// <summary>The decision asked for (not given to strategies).</summary>
    public Decision TargetTactic;

    /// <summary>Centre of the whole-fish bounding circle, mm.</summary>
    public Xna.Vector3 CollisionModelCenterPositionMm;

    /// <summary>Radius of the whole-fish bounding circle, mm: (L + L1 + L2 + L3) / 2.</summary>
    public int CollisionModelRadiusMm;

    /// <summary>
    /// Seven outline points, mm: [0] the head tip (L/2 + H ahead of <see cref="PositionMm"/>), [1] the
    /// head's left corner, [2] the left pectoral fin tip, [3] the caudal fin's left tip, [4] its right
    /// tip, [5] the right pectoral fin tip, [6] the head's right corner.
    /// </summary>
    public List<Xna.Vector3> PolygonVertices = new(7);

    /// <summary>Centre of the body bounding circle, mm.</summary>
    public Xna.Vector3 CollisionModelBodyCenterPositionMm;

    /// <summary>Radius of the body bounding circle, mm: L / 2.</summary>
    public int CollisionModelBodyRadiusMm;

    /// <summary>Centre of the tail bounding circle, mm.</summary>
    public Xna.Vector3 CollisionModelTailCenterPositionMm;

    /// <summary>Radius of the tail bounding circle, mm: (L1 + L2 + L3) / 2.</summary>
    public int CollisionModelTailRadiusMm;

    /// <summary>Left pectoral fin polygon (4 points), mm.</summary>
    public List<Xna.Vector3> LeftPectoralPolygonVertices = new(4);

    /// <summary>Right pectoral fin polygon (4 points), mm.</summary>
    public List<Xna.Vector3> RightPectoralPolygonVertices = new(4);

    /// <summary>Body polygon: head left corner, head tip, head right corner, rear right, rear left, mm.</summary>
    public List<Xna.Vector3> BodyPolygonVertices = new(5);

    /// <summary>Tail segment 1 polygon (4 points), mm.</summary>
    public List<Xna.Vector3> Tail1PolygonVertices = new(4);

    /// <summary>Tail segment 2 polygon (4 points), mm.</summary>
    public List<Xna.Vector3> Tail2PolygonVertices = new(4);

    /// <summary>Tail segment 3 polygon (4 points), mm.</summary>
    public List<Xna.Vector3> Tail3PolygonVertices = new(4);

    /// <summary>Left half of the caudal fin (3 points), mm.</summary>
    public List<Xna.Vector3> LeftCaudalFinVertices = new(3);

    /// <summary>Right half of the caudal fin (3 points), mm.</summary>
    public List<Xna.Vector3> RightCaudalFinVertices = new(3);

    /// <summary>The original's contact-depth thresholds (obstacle, fish, ball, border); zero here.</summary>
    public List<float> TransactionVectorThreshold = new(4);

    /// <summary>Last cycle's outline (not given to strategies: zeros).</summary>
    public List<Xna.Vector3> PrePolygonVertices = new(7);

    /// <summary>This cycle's contacts of the fish (not given to strategies).</summary>
    public List<CollisionType> Collision = new();

    /// <summary>Body colour (display only).</summary>
    public Color ColorFish;

    /// <summary>Number colour (display only).</summary>
    public Color ColorId;

    /// <summary>Draw counter of the original (display only).</summary>
    public int CountDrawing;

    /// <summary>Trajectory points of the original's display (empty).</summary>
    public List<Point> TrajectoryPoints = new();

    /// <summary>Radius of the body rectangle's circumcircle, mm.</summary>
    public int FishBodyRadiusMm;

    /// <summary>Sets the reference sizes and the radii derived from them.</summary>
    public void SetFish()
    {
        BodyLength = 160;
        BodyWidth = 45;
        HeadLength = 30;
        TailJointLength1 = 88;
        TailJointLength2 = 66;
        TailJointLength3 = 55;
        UpdateRadii();
    }

    /// <summary>Recomputes the bounding radii from the sizes (integer mm, as the original).</summary>
    public void UpdateRadii()
    {
        CollisionModelRadiusMm = (BodyLength + TailJointLength1 + TailJointLength2 + TailJointLength3) / 2;
        CollisionModelBodyRadiusMm = BodyLength / 2;
        CollisionModelTailRadiusMm = (TailJointLength1 + TailJointLength2 + TailJointLength3) / 2;
        FishBodyRadiusMm = (int)Math.Sqrt((BodyLength * BodyLength) + (BodyWidth * BodyWidth)) / 2;
    }

    /// <summary>Sets speeds, turn rate, decisions and tail angles back to rest.</summary>
    public void ResetSomeLocomotionPara()
    {
        VelocityMmPs = PreVelocityMmPs = 0f;
        VelocityDirectionRad = PreVelocityDirectionRad = 0f;
        AngularVelocityRadPs = PreAngularVelocityRadPs = 0f;
        Tactic.VCode = PreTactic.VCode = TargetTactic.VCode = 0;
        Tactic.TCode = PreTactic.TCode = TargetTactic.TCode = 7;
        TailToBodyAngle1 = TailToBodyAngle2 = TailToBodyAngle3 = 0f;
    }

    /// <summary>A deep copy of what the original copies for strategies (pose, speeds, sizes, tail angles, vertices, variables).</summary>
    /// <returns>A new <see cref="RoboFish"/>.</returns>
    public virtual object Clone()
    {
        var copy = new RoboFish();
        CopyTo(copy);
        return copy;
    }

    /// <summary>Copies what the original copies for strategies onto <paramref name="target"/>.</summary>
    /// <param name="target">The fish to overwrite (its lists must have their standard lengths).</param>
    public void CopyTo(RoboFish target)
    {
        ArgumentNullException.ThrowIfNull(target);
        target.PositionMm = PositionMm;
        target.BodyDirectionRad = BodyDirectionRad;
        target.VelocityMmPs = VelocityMmPs;
        target.VelocityDirectionRad = VelocityDirectionRad;
        target.AngularVelocityRadPs = AngularVelocityRadPs;
        target.HeadLength = HeadLength;
        target.BodyLength = BodyLength;
        target.BodyWidth = BodyWidth;
        target.TailJointLength1 = TailJointLength1;
        target.TailJointLength2 = TailJointLength2;
        target.TailJointLength3 = TailJointLength3;
        target.CollisionModelRadiusMm = CollisionModelRadiusMm;
        target.CollisionModelBodyRadiusMm = CollisionModelBodyRadiusMm;
        target.CollisionModelTailRadiusMm = CollisionModelTailRadiusMm;
        target.FishBodyRadiusMm = FishBodyRadiusMm;
        target.CollisionModelCenterPositionMm = CollisionModelCenterPositionMm;
        target.CollisionModelBodyCenterPositionMm = CollisionModelBodyCenterPositionMm;
        target.CollisionModelTailCenterPositionMm = CollisionModelTailCenterPositionMm;
        target.TailToBodyAngle1 = TailToBodyAngle1;
        target.TailToBodyAngle2 = TailToBodyAngle2;
        target.TailToBodyAngle3 = TailToBodyAngle3;
        Copy(PolygonVertices, target.PolygonVertices);
        Copy(BodyPolygonVertices, target.BodyPolygonVertices);
        Copy(Tail1PolygonVertices, target.Tail1PolygonVertices);
        Copy(Tail2PolygonVertices, target.Tail2PolygonVertices);
        Copy(Tail3PolygonVertices, target.Tail3PolygonVertices);
        Copy(LeftPectoralPolygonVertices, target.LeftPectoralPolygonVertices);
        Copy(RightPectoralPolygonVertices, target.RightPectoralPolygonVertices);
        Copy(LeftCaudalFinVertices, target.LeftCaudalFinVertices);
        Copy(RightCaudalFinVertices, target.RightCaudalFinVertices);
        target.HtFishVariables = (Hashtable)HtFishVariables.Clone();
    }

    private static void Copy(List<Xna.Vector3> from, List<Xna.Vector3> to)
    {
        to.Clear();
        to.AddRange(from);
    }
}
