using System;
using System.Numerics;
using URWPGSim2D.Collision.Fish;
using URWPGSim2D.Collision.Geometry;
using URWPGSim2D.Collision.Shapes;

namespace URWPGSim2D.Collision.Benchmarks.Fish;

/// <summary>
/// FROZEN BASELINE (benchmarks only): the work <c>FishModel.SetPose</c> did before this
/// optimisation (commit fb57fc1), on its own buffers, so that before and after are measured in
/// the same run: every vertex, normal and merged SAT axis rotated one at a time, the leaf slabs
/// projected in double and rounded outward, and the tail group and root circles found by an
/// exact incremental minimum-enclosing-circle search over the extreme-first vertex orders.
/// </summary>
internal sealed class FishPoseBaseline
{
    private readonly FishTemplate _template;
    private readonly Vector2[] _axesLocal = new Vector2[FishLeafLayout.VertexCount];
    private readonly byte[] _axisCounts = new byte[FishLeafLayout.LeafCount];
    private readonly int[] _tailOrder;
    private readonly int[] _allOrder;
    private readonly Vector2[] _vertices = new Vector2[FishLeafLayout.VertexCount];
    private readonly Vector2[] _normals = new Vector2[FishLeafLayout.VertexCount];
    private readonly Vector2[] _axes = new Vector2[FishLeafLayout.VertexCount];
    private readonly Vector4[] _slabMin = new Vector4[FishLeafLayout.LeafCount];
    private readonly Vector4[] _slabMax = new Vector4[FishLeafLayout.LeafCount];
    private readonly Vector2[] _orderedPoints;

    public FishPoseBaseline(FishSize size)
    {
        _template = new FishTemplate(size);
        var normals = _template.Normals;
        for (int leaf = 0; leaf < FishLeafLayout.LeafCount; leaf++)
        {
            int at = FishLeafLayout.Offset(leaf), axes = 0;
            for (int i = 0; i < FishLeafLayout.Count(leaf); i++)
            {
                bool parallel = false;
                for (int k = 0; k < axes; k++)
                {
                    parallel |= MathF.Abs(XZPlane.Cross(_axesLocal[at + k], normals[at + i])) <= 1e-6f;
                }

                if (!parallel)
                {
                    _axesLocal[at + axes++] = normals[at + i];
                }
            }

            _axisCounts[leaf] = (byte)axes;
        }

        _tailOrder = ExtremeFirstOrder(FishLeafLayout.BodyGroupEnd);
        _allOrder = ExtremeFirstOrder(0);
        _orderedPoints = new Vector2[_allOrder.Length];
    }

    public Circle Root { get; private set; }

    public Circle TailGroup { get; private set; }

    public Circle BodyGroup { get; private set; }

    public Aabb Bounds { get; private set; }

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

            for (int i = at, axesEnd = at + _axisCounts[leaf]; i < axesEnd; i++)
            {
                _axes[i] = Rotate(r, _axesLocal[i]);
            }

            KDop8.Slabs(_vertices.AsSpan(at, end - at), out Vector4 min, out Vector4 max);
            _slabMin[leaf] = min;
            _slabMax[leaf] = max;
            allMin = Vector4.Min(allMin, min);
            allMax = Vector4.Max(allMax, max);
        }

        Bounds = new Aabb(new Vector2(allMin.X, allMin.Y), new Vector2(allMax.X, allMax.Y));
        var body = _template.BodyGroup;
        BodyGroup = EnclosingCircle.WithSlack(origin[0] + Rotate(rotation[0], body.Center), body.Radius);
        TailGroup = MinimumCircle(_tailOrder);
        Root = MinimumCircle(_allOrder);
    }

    private static Vector2 Rotate(Vector2 r, Vector2 local) => new(local.X * r.X - local.Y * r.Y, local.X * r.Y + local.Y * r.X);

    private static Vector2 Direction(float angle)
    {
        (float sin, float cos) = MathF.SinCos(angle);
        return new Vector2(cos, sin);
    }

    private Circle MinimumCircle(ReadOnlySpan<int> order)
    {
        var points = _orderedPoints.AsSpan(0, order.Length);
        for (int i = 0; i < order.Length; i++)
        {
            points[i] = _vertices[order[i]];
        }

        return EnclosingCircle.Minimum(points);
    }

    // Distinct vertices of leaves firstLeaf..7 in the straight pose, farthest from their circle's centre first.
    private int[] ExtremeFirstOrder(int firstLeaf)
    {
        var local = _template.Vertices;
        var size = _template.Size;
        var straight = new System.Collections.Generic.List<Vector2>();
        var index = new System.Collections.Generic.List<int>();
        for (int leaf = firstLeaf; leaf < FishLeafLayout.LeafCount; leaf++)
        {
            int frame = FishLeafLayout.Frame(leaf);
            float originX = frame switch
            {
                0 => 0f,
                1 => -0.5f * size.Length,
                2 => -0.5f * size.Length - size.Joint1,
                _ => -0.5f * size.Length - size.Joint1 - size.Joint2,
            };
            for (int k = 0; k < FishLeafLayout.Count(leaf); k++)
            {
                int at = FishLeafLayout.Offset(leaf) + k;
                bool duplicate = false;
                foreach (int other in index)
                {
                    duplicate |= FrameOf(other) == frame && local[other] == local[at];
                }

                if (!duplicate)
                {
                    straight.Add(local[at] + new Vector2(originX, 0f));
                    index.Add(at);
                }
            }
        }

        Vector2 c = EnclosingCircle.Minimum(straight.ToArray()).Center;
        var order = index.ToArray();
        var distance = new float[order.Length];
        for (int i = 0; i < order.Length; i++)
        {
            distance[i] = -Vector2.DistanceSquared(straight[i], c);
        }

        Array.Sort(distance, order);
        return order;
    }

    private static int FrameOf(int at)
    {
        for (int leaf = FishLeafLayout.LeafCount - 1; leaf >= 0; leaf--)
        {
            if (at >= FishLeafLayout.Offset(leaf))
            {
                return FishLeafLayout.Frame(leaf);
            }
        }

        return 0;
    }
}
