namespace URWPGSim2D.Collision.Fish;

/// <summary>
/// The eight leaf polygons of the reference fish model, each in its own rigid frame, mm.
/// A frame point (a, b) has a along the frame's axis (forward) and b to the fish's right; it
/// maps to the world point origin + a·u − b·n with u = (cos α, sin α), n = (sin α, −cos α),
/// i.e. origin + R(α)·(a, b) — a rotation, so windings are the same in both.
/// </summary>
/// <remarks>
/// Frame 0 is the body (origin P, α = θ). Frame i = 1..3 is tail segment i (origin Sᵢ, its
/// joint, α = θ + φᵢ); the segment runs backward to Eᵢ = Sᵢ − Lᵢ·dᵢ, i.e. frame point (−Lᵢ, 0).
/// The caudal fin lives in frame 3 (rigid; the original scaled it by |cos θ|, this does not).
/// </remarks>
internal static class FishLocalGeometry
{
    /// <summary>Half-width of tail segment i at its start, as a fraction of its length (reference values).</summary>
    public const float StartHalfWidth1 = 0.266112f, StartHalfWidth2 = 0.231336f, StartHalfWidth3 = 0.115668f;

    /// <summary>Half-width of tail segment i at its end, as a fraction of its length (reference values).</summary>
    public const float EndHalfWidth1 = 0.2193408f, EndHalfWidth2 = 0.14994f, EndHalfWidth3 = 0.089964f;

    // Fixed offsets of the reference, mm: pectoral fin tips beyond the body side, caudal tips and notch.
    private const float PectoralOuter = 37.5f, PectoralInner = 25f;
    private const float CaudalLeftTip = 50f, CaudalRightTip = 35f, CaudalNotch = 10f;

    /// <summary>
    /// Writes the 31 frame-local vertices, leaf after leaf in <see cref="FishPart"/> order and
    /// each leaf in the reference's vertex order (not yet normalised to counter-clockwise).
    /// </summary>
    public static void Write(in FishSize size, Span<Vector2> v)
    {
        float l = size.Length, hw = 0.5f * size.Width;

        // Left pectoral, body with head, right pectoral: body frame.
        v[0] = new(-7f * l / 24f, -hw - PectoralOuter);
        v[1] = new(-7f * l / 24f, -hw - PectoralInner);
        v[2] = new(-l / 12f, -hw);
        v[3] = new(l / 4f, -hw);
        v[4] = new(0.5f * l, -hw);
        v[5] = new(0.5f * l + size.Head, 0f);
        v[6] = new(0.5f * l, hw);
        v[7] = new(-0.5f * l, hw);
        v[8] = new(-0.5f * l, -hw);
        for (int i = 0; i < 4; i++)
        {
            v[9 + i] = new(v[i].X, -v[i].Y);
        }

        // Tail segments: Sᵢ ∓ hᵢ·nᵢ, Eᵢ ± h'ᵢ·nᵢ, in frame i (n ↔ frame point (0, −1)).
        TailSegment(v[13..17], size.Joint1, StartHalfWidth1, EndHalfWidth1);
        TailSegment(v[17..21], size.Joint2, StartHalfWidth2, EndHalfWidth2);
        TailSegment(v[21..25], size.Joint3, StartHalfWidth3, EndHalfWidth3);

        // Caudal fin in frame 3: Aₖ = frame point (−k·L3, 0); tips and notch offset along n3.
        float l3 = size.Joint3, end3 = EndHalfWidth3 * l3;
        v[25] = new(-2f * l3, -CaudalLeftTip);
        v[26] = new(-1.8f * l3, -CaudalNotch);
        v[27] = new(-l3, end3);
        v[28] = new(-1.8f * l3, CaudalRightTip);
        v[29] = new(-1.8f * l3, -CaudalNotch);
        v[30] = new(-l3, -end3);
    }

    /// <summary>The first leaf whose vertices are collinear for this size (relative tolerance 1e-5), or null.</summary>
    public static FishPart? FindDegenerateLeaf(in FishSize size)
    {
        Span<Vector2> v = stackalloc Vector2[FishLeafLayout.VertexCount];
        Write(size, v);
        for (int leaf = 0; leaf < FishLeafLayout.LeafCount; leaf++)
        {
            var p = v.Slice(FishLeafLayout.Offset(leaf), FishLeafLayout.Count(leaf));
            Vector2 lo = p[0], hi = p[0];
            foreach (var q in p)
            {
                lo = Vector2.Min(lo, q);
                hi = Vector2.Max(hi, q);
            }

            float extent = MathF.Max(hi.X - lo.X, hi.Y - lo.Y);
            if (MathF.Abs(ConvexPolygon.SignedArea2(p)) <= 1e-5f * extent * extent)
            {
                return (FishPart)leaf;
            }
        }

        return null;
    }

    private static void TailSegment(Span<Vector2> v, float length, float startRatio, float endRatio)
    {
        float h = startRatio * length, hEnd = endRatio * length;
        v[0] = new(0f, h);
        v[1] = new(0f, -h);
        v[2] = new(-length, -hEnd);
        v[3] = new(-length, hEnd);
    }
}
