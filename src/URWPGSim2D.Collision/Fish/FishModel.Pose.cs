using System;
using System.Numerics;
using System.Runtime.CompilerServices;
using System.Runtime.Intrinsics;
using URWPGSim2D.Collision.Geometry;
using URWPGSim2D.Collision.Shapes;

namespace URWPGSim2D.Collision.Fish;

/// <content>Rebuilding the leaves and the bounding volumes for a new pose, in place.</content>
public sealed partial class FishModel
{
    /// <summary>
    /// Moves the model to <paramref name="pose"/>: every leaf vertex and normal is its
    /// frame-local value rotated by the frame's angle and moved to the frame's origin (body:
    /// P and θ; tail segment i: Sᵢ and θ + φᵢ with S1 = P − (L/2)·u, Sᵢ₊₁ = Sᵢ − Lᵢ·dᵢ), then
    /// the leaf 8-DOPs, <see cref="Bounds"/> and the three circles are rebuilt. Allocates nothing.
    /// </summary>
    /// <param name="pose">The new pose (validated by its constructor).</param>
    public void SetPose(in FishPose pose)
    {
        var size = _template.Size;
        Vector2 r0 = Direction(pose.Heading);
        Vector2 r1 = Direction(pose.Heading + pose.Joint1);
        Vector2 r2 = Direction(pose.Heading + pose.Joint2);
        Vector2 r3 = Direction(pose.Heading + pose.Joint3);
        Vector2 o0 = pose.Position;
        Vector2 o1 = o0 - _template.HalfLength * r0;
        Vector2 o2 = o1 - size.Joint1 * r1;
        Vector2 o3 = o2 - size.Joint2 * r2;
        PlaceFrames(o0, r0, o1, r1, o2, r2, o3, r3);
        Vector4 bodyMin, bodyMax, tailMin, tailMax;
        if (Vector128.IsHardwareAccelerated)
        {
            // One outward pad for every leaf: no vertex has |x| + |z| beyond |Px| + |Pz| + √2·reach.
            var outward = FloatSlabs.Outward(MathF.Abs(pose.Position.X) + MathF.Abs(pose.Position.Y) + _template.SlabReach);
            AllLeafSlabs(outward, out bodyMin, out bodyMax, out tailMin, out tailMax);
        }
        else
        {
            AllLeafSlabsScalar(out bodyMin, out bodyMax, out tailMin, out tailMax);
        }

        Vector4 allMin = Vector128.MinNative(bodyMin.AsVector128(), tailMin.AsVector128()).AsVector4();
        Vector4 allMax = Vector128.MaxNative(bodyMax.AsVector128(), tailMax.AsVector128()).AsVector4();
        Pose = pose;
        Forward = r0;
        HeadTip = pose.Position + _template.HeadReach * r0;
        Bounds = Aabb.Trusted(new Vector2(allMin.X, allMin.Y), new Vector2(allMax.X, allMax.Y));
        RebuildCircles(o0, r0, tailMin, tailMax, allMin, allMax);
    }

    /// <summary>R(α)·(a, b) = (a·cos α − b·sin α, a·sin α + b·cos α), with r = (cos α, sin α).</summary>
    internal static Vector2 Rotate(Vector2 r, Vector2 local) => RigidTransform.Rotate(r, local);

    private static Vector2 Direction(float angle)
    {
        (float sin, float cos) = MathF.SinCos(angle);
        return new Vector2(cos, sin);
    }

    // The four frames; each is inlined with its constant vertex range.
    private void PlaceFrames(Vector2 o0, Vector2 r0, Vector2 o1, Vector2 r1, Vector2 o2, Vector2 r2, Vector2 o3, Vector2 r3)
    {
        PlaceFrame(0, o0, r0);
        PlaceFrame(1, o1, r1);
        PlaceFrame(2, o2, r2);
        PlaceFrame(3, o3, r3);
    }

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    private void PlaceFrame(int frame, Vector2 origin, Vector2 rotation)
    {
        int start = FishLeafLayout.FrameStart(frame), count = FishLeafLayout.FrameStart(frame + 1) - start;
        RigidTransform.PlaceAndTurn(
            _template.Vertices.Slice(start, count), _template.Normals.Slice(start, count),
            _vertices.AsSpan(start, count), _normals.AsSpan(start, count), origin, rotation);
    }

    // Every leaf's slabs, stored, and the union over each group (not padded: only centres come from them).
    private void AllLeafSlabs(Vector128<float> outward, out Vector4 bodyMin, out Vector4 bodyMax, out Vector4 tailMin, out Vector4 tailMax)
    {
        var bodyLo = LeafSlabs(0, outward, out var bodyHi);
        bodyLo = Vector128.MinNative(bodyLo, LeafSlabs(1, outward, out var hi));
        bodyHi = Vector128.MaxNative(bodyHi, hi);
        bodyLo = Vector128.MinNative(bodyLo, LeafSlabs(2, outward, out hi));
        bodyHi = Vector128.MaxNative(bodyHi, hi);
        var tailLo = LeafSlabs(3, outward, out var tailHi);
        for (int leaf = 4; leaf < FishLeafLayout.LeafCount; leaf++)
        {
            tailLo = Vector128.MinNative(tailLo, LeafSlabs(leaf, outward, out hi));
            tailHi = Vector128.MaxNative(tailHi, hi);
        }

        bodyMin = bodyLo.AsVector4();
        bodyMax = bodyHi.AsVector4();
        tailMin = tailLo.AsVector4();
        tailMax = tailHi.AsVector4();
    }

    // The padded slabs of one leaf, stored; returns them (lower, and upper in hi).
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    private Vector128<float> LeafSlabs(int leaf, Vector128<float> outward, out Vector128<float> hi)
    {
        FloatSlabs.Projections(_vertices.AsSpan(FishLeafLayout.Offset(leaf), FishLeafLayout.Count(leaf)), out var lo, out hi);
        lo -= outward;
        hi += outward;
        _slabMin[leaf] = lo.AsVector4();
        _slabMax[leaf] = hi.AsVector4();
        return lo;
    }

    private void AllLeafSlabsScalar(out Vector4 bodyMin, out Vector4 bodyMax, out Vector4 tailMin, out Vector4 tailMax)
    {
        bodyMin = tailMin = new(float.PositiveInfinity);
        bodyMax = tailMax = new(float.NegativeInfinity);
        for (int leaf = 0; leaf < FishLeafLayout.LeafCount; leaf++)
        {
            FloatSlabs.OfScalar(_vertices.AsSpan(FishLeafLayout.Offset(leaf), FishLeafLayout.Count(leaf)), out Vector4 min, out Vector4 max);
            _slabMin[leaf] = min;
            _slabMax[leaf] = max;
            if (leaf < FishLeafLayout.BodyGroupEnd)
            {
                bodyMin = Vector4.Min(bodyMin, min);
                bodyMax = Vector4.Max(bodyMax, max);
            }
            else
            {
                tailMin = Vector4.Min(tailMin, min);
                tailMax = Vector4.Max(tailMax, max);
            }
        }
    }

    // Body group: rigid, its minimum circle moves with the body. Tail group and root: centred at
    // the centre of the smallest fixed-axis octagon around their slabs, radius to the farthest
    // vertex: at most 1/cos 22.5° of the minimum radius (see OctagonCentre). The root holds every
    // leaf but not necessarily the group circles, which bulge past the fish (holding them would
    // cost up to 1.28 times the minimum even with the best circle around both).
    private void RebuildCircles(Vector2 position, Vector2 bodyRotation, Vector4 tailMin, Vector4 tailMax, Vector4 allMin, Vector4 allMax)
    {
        var body = _template.BodyGroup;
        BodyGroup = EnclosingCircle.WithSlack(position + Rotate(bodyRotation, body.Center), body.Radius);
        Vector2 tailCentre = OctagonCentre.Of(tailMin, tailMax);
        Vector2 rootCentre = OctagonCentre.Of(allMin, allMax);
        TailGroup = EnclosingCircle.Enclosing(_vertices.AsSpan(FishLeafLayout.TailGroupFirstVertex), tailCentre);
        Root = EnclosingCircle.Enclosing(_vertices, rootCentre);
    }
}
