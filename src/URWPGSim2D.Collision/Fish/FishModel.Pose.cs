using System;
using System.Numerics;
using URWPGSim2D.Collision.Shapes;

namespace URWPGSim2D.Collision.Fish;

/// <content>Rebuilding the leaves and the bounding volumes for a new pose, in place.</content>
public sealed partial class FishModel
{
    /// <summary>
    /// Moves the model to <paramref name="pose"/>: every leaf vertex, normal and axis is its
    /// frame-local value rotated by the frame's angle and moved to the frame's origin (body:
    /// P and θ; tail segment i: Sᵢ and θ + φᵢ with S1 = P − (L/2)·u, Sᵢ₊₁ = Sᵢ − Lᵢ·dᵢ), then
    /// the leaf 8-DOPs, <see cref="Bounds"/> and the three circles are rebuilt. Allocates nothing.
    /// </summary>
    /// <param name="pose">The new pose (validated by its constructor).</param>
    public void SetPose(in FishPose pose)
    {
        var size = _template.Size;
        Span<Vector2> origin = stackalloc Vector2[FishLeafLayout.FrameCount];
        Span<Vector2> rotation = stackalloc Vector2[FishLeafLayout.FrameCount];
        rotation[0] = Direction(pose.Heading);
        rotation[1] = Direction(pose.Heading + pose.Joint1);
        rotation[2] = Direction(pose.Heading + pose.Joint2);
        rotation[3] = Direction(pose.Heading + pose.Joint3);
        origin[0] = pose.Position;
        origin[1] = pose.Position - 0.5f * size.Length * rotation[0];
        origin[2] = origin[1] - size.Joint1 * rotation[1];
        origin[3] = origin[2] - size.Joint2 * rotation[2];

        var localV = _template.Vertices;
        var localN = _template.Normals;
        var localA = _template.Axes;
        Vector4 allMin = new(float.PositiveInfinity), allMax = new(float.NegativeInfinity);
        for (int leaf = 0; leaf < FishLeafLayout.LeafCount; leaf++)
        {
            int frame = FishLeafLayout.Frame(leaf);
            Vector2 o = origin[frame], r = rotation[frame];
            int at = FishLeafLayout.Offset(leaf), end = at + FishLeafLayout.Count(leaf);
            for (int i = at; i < end; i++)
            {
                _vertices[i] = o + Rotate(r, localV[i]);
                _normals[i] = Rotate(r, localN[i]);
            }

            for (int i = at, axesEnd = at + _template.AxisCount(leaf); i < axesEnd; i++)
            {
                _axes[i] = Rotate(r, localA[i]);
            }

            KDop8.Slabs(_vertices.AsSpan(at, end - at), out Vector4 min, out Vector4 max);
            _slabMin[leaf] = min;
            _slabMax[leaf] = max;
            allMin = Vector4.Min(allMin, min);
            allMax = Vector4.Max(allMax, max);
        }

        Pose = pose;
        Forward = rotation[0];
        HeadTip = pose.Position + (0.5f * size.Length + size.Head) * rotation[0];
        Bounds = new Aabb(new Vector2(allMin.X, allMin.Y), new Vector2(allMax.X, allMax.Y));
        RebuildCircles(origin[0], rotation[0]);
    }

    /// <summary>R(α)·(a, b) = (a·cos α − b·sin α, a·sin α + b·cos α), with r = (cos α, sin α).</summary>
    internal static Vector2 Rotate(Vector2 r, Vector2 local) =>
        new(local.X * r.X - local.Y * r.Y, local.X * r.Y + local.Y * r.X);

    private static Vector2 Direction(float angle)
    {
        (float sin, float cos) = MathF.SinCos(angle);
        return new Vector2(cos, sin);
    }

    private void RebuildCircles(Vector2 position, Vector2 bodyRotation)
    {
        var body = _template.BodyGroup;
        BodyGroup = EnclosingCircle.WithSlack(position + Rotate(bodyRotation, body.Center), body.Radius);

        TailGroup = MinimumCircle(_template.TailOrder);
        Root = MinimumCircle(_template.AllOrder);
    }

    // The minimum enclosing circle of the vertices listed in `order` (likely boundary points first).
    private Circle MinimumCircle(ReadOnlySpan<int> order)
    {
        var points = _orderedPoints.AsSpan(0, order.Length);
        for (int i = 0; i < order.Length; i++)
        {
            points[i] = _vertices[order[i]];
        }

        return EnclosingCircle.Minimum(points);
    }
}
