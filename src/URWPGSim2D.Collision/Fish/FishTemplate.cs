using System;
using System.Numerics;
using URWPGSim2D.Collision.Geometry;
using URWPGSim2D.Collision.Shapes;

namespace URWPGSim2D.Collision.Fish;

/// <summary>
/// Everything about a fish that depends on its size only, computed once: each leaf in its
/// rigid frame (vertices counter-clockwise, outward unit edge normals, SAT axes with parallel
/// edges merged), the body group's minimum enclosing circle in the body frame, and the orders
/// in which the tail group's and the whole fish's distinct vertices are fed to the
/// enclosing-circle search (likely boundary points first).
/// </summary>
internal sealed class FishTemplate
{
    private readonly Vector2[] _vertices = new Vector2[FishLeafLayout.VertexCount];
    private readonly Vector2[] _normals = new Vector2[FishLeafLayout.VertexCount];
    private readonly Vector2[] _axes = new Vector2[FishLeafLayout.VertexCount];
    private readonly byte[] _axisCounts = new byte[FishLeafLayout.LeafCount];
    private readonly int[] _tailOrder;
    private readonly int[] _allOrder;

    public FishTemplate(in FishSize size)
    {
        Size = size;
        FishLocalGeometry.Write(size, _vertices);
        for (int leaf = 0; leaf < FishLeafLayout.LeafCount; leaf++)
        {
            int at = FishLeafLayout.Offset(leaf), n = FishLeafLayout.Count(leaf);
            var v = _vertices.AsSpan(at, n);
            if (ConvexPolygon.SignedArea2(v) < 0f)
            {
                v.Reverse();
            }

            int axes = 0;
            for (int i = 0; i < n; i++)
            {
                Vector2 normal = Vector2.Normalize(XZPlane.RightPerp(v[(i + 1) % n] - v[i]));
                _normals[at + i] = normal;
                if (!HasParallel(_axes.AsSpan(at, axes), normal))
                {
                    _axes[at + axes++] = normal;
                }
            }

            _axisCounts[leaf] = (byte)axes;
        }

        BodyGroup = EnclosingCircle.Minimum(_vertices.AsSpan(0, FishLeafLayout.TailGroupFirstVertex));
        _tailOrder = ExtremeFirstOrder(FishLeafLayout.BodyGroupEnd);
        _allOrder = ExtremeFirstOrder(0);
    }

    /// <summary>The size this template was built for.</summary>
    public FishSize Size { get; }

    /// <summary>Frame-local vertices of all leaves, counter-clockwise per leaf, packed (see <see cref="FishLeafLayout"/>).</summary>
    public ReadOnlySpan<Vector2> Vertices => _vertices;

    /// <summary>Frame-local outward unit normal of edge i → i+1 of each leaf, packed like the vertices.</summary>
    public ReadOnlySpan<Vector2> Normals => _normals;

    /// <summary>Frame-local SAT axes of each leaf, packed from the leaf's vertex offset, <see cref="AxisCount"/> each.</summary>
    public ReadOnlySpan<Vector2> Axes => _axes;

    /// <summary>The body group's minimum enclosing circle in the body frame (centre relative to P).</summary>
    public Circle BodyGroup { get; }

    /// <summary>Packed indices of the tail group's distinct vertices, farthest from the straight tail's centre first.</summary>
    public ReadOnlySpan<int> TailOrder => _tailOrder;

    /// <summary>Packed indices of all distinct vertices, farthest from the straight fish's centre first.</summary>
    public ReadOnlySpan<int> AllOrder => _allOrder;

    /// <summary>Number of SAT axes of a leaf (its edge normals with parallel ones merged).</summary>
    public int AxisCount(int leaf) => _axisCounts[leaf];

    private static bool HasParallel(ReadOnlySpan<Vector2> axes, Vector2 normal)
    {
        foreach (var a in axes)
        {
            if (MathF.Abs(XZPlane.Cross(a, normal)) <= 1e-6f)
            {
                return true;
            }
        }

        return false;
    }

    // The vertices of leaves firstLeaf..7 in the straight pose (all frames along +X); shared
    // vertices of the caudal fin and tail segment 3 appear once. Sorted by decreasing distance
    // from their enclosing circle's centre, so the incremental search meets the boundary first.
    private int[] ExtremeFirstOrder(int firstLeaf)
    {
        Span<Vector2> straight = stackalloc Vector2[FishLeafLayout.VertexCount];
        Span<int> index = stackalloc int[straight.Length];
        int count = 0;
        for (int leaf = firstLeaf; leaf < FishLeafLayout.LeafCount; leaf++)
        {
            float originX = FrameOriginX(FishLeafLayout.Frame(leaf));
            for (int k = 0; k < FishLeafLayout.Count(leaf); k++)
            {
                int at = FishLeafLayout.Offset(leaf) + k;
                Vector2 p = _vertices[at] + new Vector2(originX, 0f);
                if (!SameFrameDuplicate(index[..count], at))
                {
                    straight[count] = p;
                    index[count++] = at;
                }
            }
        }

        Vector2 c = EnclosingCircle.Minimum(straight[..count]).Center;
        var order = new int[count];
        var distance = new float[count];
        for (int i = 0; i < count; i++)
        {
            order[i] = index[i];
            distance[i] = -Vector2.DistanceSquared(straight[i], c);
        }

        Array.Sort(distance, order);
        return order;
    }

    // True when an already listed vertex has the same frame and frame-local point (it moves identically).
    private bool SameFrameDuplicate(ReadOnlySpan<int> listed, int at)
    {
        int frame = FrameOfVertex(at);
        foreach (int other in listed)
        {
            if (FrameOfVertex(other) == frame && _vertices[other] == _vertices[at])
            {
                return true;
            }
        }

        return false;
    }

    private static int FrameOfVertex(int at)
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

    // Straight pose, P = 0: frame i's origin on the X axis.
    private float FrameOriginX(int frame) => frame switch
    {
        0 => 0f,
        1 => -0.5f * Size.Length,
        2 => -0.5f * Size.Length - Size.Joint1,
        _ => -0.5f * Size.Length - Size.Joint1 - Size.Joint2,
    };
}
