namespace URWPGSim2D.Collision.Fish;

/// <content>Rebuilding the leaves and the bounding volumes for a new pose, in place.</content>
public sealed partial class FishModel
{
    /// <summary>
    /// Moves the model to <paramref name="pose"/>: every leaf vertex and normal is its
    /// frame-local value rotated by the frame's angle and moved to the frame's origin (body:
    /// P and θ; tail segment i: Sᵢ and θ + φᵢ with S1 = P − (L/2)·u, Sᵢ₊₁ = Sᵢ − Lᵢ·dᵢ), then
    /// the leaf 8-DOPs and <see cref="Bounds"/> are rebuilt and the three circles moved with the
    /// body (the tail group and root circles are recomputed in the body frame only when a joint
    /// angle changed). Allocates nothing.
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
        Vector4 allMin, allMax;
        if (Vector128.IsHardwareAccelerated)
        {
            // One outward pad for every leaf: no vertex has |x| + |z| beyond |Px| + |Pz| + √2·reach.
            var outward = FloatSlabs.Outward(MathF.Abs(pose.Position.X) + MathF.Abs(pose.Position.Y) + _template.SlabReach);
            AllLeafSlabs(outward, out allMin, out allMax);
        }
        else
        {
            AllLeafSlabsScalar(out allMin, out allMax);
        }

        Pose = pose;
        Forward = r0;
        HeadTip = pose.Position + _template.HeadReach * r0;
        Bounds = Aabb.Trusted(new Vector2(allMin.X, allMin.Y), new Vector2(allMax.X, allMax.Y));
        RebuildCircles(pose, r0);
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

    // Every leaf's slabs, stored, and their union (whose x and z slabs are exact: Bounds).
    private void AllLeafSlabs(Vector128<float> outward, out Vector4 allMin, out Vector4 allMax)
    {
        var lo = LeafSlabs(0, outward, out var hi);
        for (int leaf = 1; leaf < FishLeafLayout.LeafCount; leaf++)
        {
            lo = Vector128.MinNative(lo, LeafSlabs(leaf, outward, out var leafHi));
            hi = Vector128.MaxNative(hi, leafHi);
        }

        allMin = lo.AsVector4();
        allMax = hi.AsVector4();
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

    private void AllLeafSlabsScalar(out Vector4 allMin, out Vector4 allMax)
    {
        allMin = new(float.PositiveInfinity);
        allMax = new(float.NegativeInfinity);
        for (int leaf = 0; leaf < FishLeafLayout.LeafCount; leaf++)
        {
            FloatSlabs.OfScalar(_vertices.AsSpan(FishLeafLayout.Offset(leaf), FishLeafLayout.Count(leaf)), out Vector4 min, out Vector4 max);
            _slabMin[leaf] = min;
            _slabMax[leaf] = max;
            allMin = Vector4.Min(allMin, min);
            allMax = Vector4.Max(allMax, max);
        }
    }

    // The three circles move rigidly with the body frame: the body group's minimum circle
    // (fixed per size) and the tail group and root circles of the current joint angles (see
    // FishShapeCircles). The world leaves are placed through the frames' own angles θ + φᵢ, not by
    // this rigid move, so the radii grow by a bound on that difference: the rounding of θ + φᵢ
    // and of the sines and cosines, times the reach (2⁻²⁰·(4 + |θ| + max |φᵢ|) radians, ample).
    // The root holds every leaf but not necessarily the group circles, which bulge past the fish
    // (holding them would cost up to 1.28 times the minimum even with the best circle around both).
    private void RebuildCircles(in FishPose pose, Vector2 bodyRotation)
    {
        Vector2 position = pose.Position;
        var body = _template.BodyGroup;
        BodyGroup = EnclosingCircle.WithSlack(position + Rotate(bodyRotation, body.Center), body.Radius);
        _shape.Update(pose.Joint1, pose.Joint2, pose.Joint3);
        float angles = 4f + MathF.Abs(pose.Heading) + MathF.Max(MathF.Abs(pose.Joint1), MathF.Max(MathF.Abs(pose.Joint2), MathF.Abs(pose.Joint3)));
        float turn = _shape.Reach * AngleRoundOff * angles;
        var tail = _shape.Tail;
        var root = _shape.Root;
        TailGroup = EnclosingCircle.WithSlack(position + Rotate(bodyRotation, tail.Center), tail.Radius + turn);
        Root = EnclosingCircle.WithSlack(position + Rotate(bodyRotation, root.Center), root.Radius + turn);
    }

    // 2⁻²⁰: radians of angle round-off per radian of |θ| + |φ| (plus 4 for the sines and cosines).
    private const float AngleRoundOff = 1f / 1048576f;
}
