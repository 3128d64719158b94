using System;
using System.Numerics;
using URWPGSim2D.Collision.Geometry;
using URWPGSim2D.Collision.Shapes;

namespace URWPGSim2D.Collision.Fish;

/// <summary>
/// Everything about a fish that depends on its size only, computed once: each leaf in its
/// rigid frame (vertices counter-clockwise, outward unit edge normals) and the body group's
/// minimum enclosing circle in the body frame.
/// </summary>
internal sealed class FishTemplate
{
    private readonly Vector2[] _vertices = new Vector2[FishLeafLayout.VertexCount];
    private readonly Vector2[] _normals = new Vector2[FishLeafLayout.VertexCount];

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

            for (int i = 0; i < n; i++)
            {
                _normals[at + i] = Vector2.Normalize(XZPlane.RightPerp(v[(i + 1) % n] - v[i]));
            }
        }

        BodyGroup = EnclosingCircle.Minimum(_vertices.AsSpan(0, FishLeafLayout.TailGroupFirstVertex));
        HalfLength = 0.5f * size.Length;
        HeadReach = 0.5f * size.Length + size.Head;
    }

    /// <summary>The size this template was built for.</summary>
    public FishSize Size { get; }

    /// <summary>L/2, mm: tail segment 1 starts at P − (L/2)·u.</summary>
    public float HalfLength { get; }

    /// <summary>L/2 + H, mm: the head tip is P + (L/2 + H)·u.</summary>
    public float HeadReach { get; }

    /// <summary>Frame-local vertices of all leaves, counter-clockwise per leaf, packed (see <see cref="FishLeafLayout"/>).</summary>
    public ReadOnlySpan<Vector2> Vertices => _vertices;

    /// <summary>Frame-local outward unit normal of edge i → i+1 of each leaf, packed like the vertices.</summary>
    public ReadOnlySpan<Vector2> Normals => _normals;

    /// <summary>The body group's minimum enclosing circle in the body frame (centre relative to P).</summary>
    public Circle BodyGroup { get; }
}
