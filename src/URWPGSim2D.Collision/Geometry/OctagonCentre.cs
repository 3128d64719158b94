using System.Runtime.InteropServices;

namespace URWPGSim2D.Collision.Geometry;

/// <summary>
/// The centre of the smallest regular octagon, with the 8-DOP's fixed face directions, that
/// contains a slab set: a cheap centre for a tight bounding circle.
/// </summary>
/// <remarks>
/// With eⱼ = (cos j·45°, sin j·45°) and sⱼ = max p·eⱼ over the shape, the octagon of apothem ρ
/// centred at c holds the shape iff eⱼ·c ≥ sⱼ − ρ for all eight j. By Helly's theorem these
/// half-planes share a point iff every opposite pair and every triple whose normals surround the
/// origin do, which gives the least ρ in closed form: the largest of the four half-widths
/// (sⱼ + sⱼ₊₄)/2 and of the eight triple values (√½·sⱼ + sⱼ₊₃ + √½·sⱼ₊₆)/(1 + √2). The centre is
/// where the binding triple's lines meet, or, for a binding width, the middle of the stretch of
/// the mid-line that the other six constraints leave.
/// <para>Why it is tight: the minimum enclosing circle (radius R) lies inside its own
/// circumscribed octagon of apothem R, so ρ ≤ R; every point of the shape then lies in the
/// octagon of apothem ρ about the centre, whose corners are ρ / cos 22.5° away. The farthest point
/// from this centre is therefore at most 1 / cos 22.5° ≈ 1.0824 times R.</para>
/// </remarks>
internal static class OctagonCentre
{
    private const float Half = KDop8.Diagonal;

    // √2 = 1 / √½.
    private const float Root2 = 1.41421356237309505f;

    // 1 / (1 + √2): the weights of a triple are √½, 1, √½.
    private const float TripleScale = 0.41421356237309505f;

    // eⱼ for j = 0..7 (arrays, not span literals: those allocate on every use in debug builds).
    private static readonly float[] Cos = [1f, Half, 0f, -Half, -1f, -Half, 0f, Half];

    private static readonly float[] Sin = [0f, Half, 1f, Half, 0f, -Half, -1f, -Half];

    /// <summary>The centre for slabs minᵢ ≤ p·aᵢ ≤ maxᵢ on the four 8-DOP axes (a non-empty set).</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static Vector2 Of(in Vector4 min, in Vector4 max) =>
        Vector256.IsHardwareAccelerated ? OfVector(min, max) : OfScalar(min, max);

    /// <summary>
    /// The same centre without vector hardware: the supports sⱼ relative to the box centre m (so
    /// that large coordinates cost no precision), the binding candidate, then its centre.
    /// </summary>
    internal static Vector2 OfScalar(in Vector4 min, in Vector4 max)
    {
        Vector2 m = BoxCentre(min, max, out Vector4 above, out Vector4 below);
        Span<float> s = stackalloc float[8];
        s[0] = above.X;
        s[1] = above.Z;
        s[2] = above.Y;
        s[3] = below.W;
        s[4] = below.X;
        s[5] = below.Z;
        s[6] = below.Y;
        s[7] = above.W;

        // The least apothem and what binds it; the first candidate in this order wins a tie.
        float rho = float.NegativeInfinity;
        int binding = 0;
        for (int j = 0; j < 4; j++)
        {
            float width = 0.5f * (s[j] + s[j + 4]);
            if (width > rho)
            {
                rho = width;
                binding = j;
            }
        }

        for (int j = 0; j < 8; j++)
        {
            float triple = ((Half * s[j]) + s[(j + 3) & 7] + (Half * s[(j + 6) & 7])) * TripleScale;
            if (triple > rho)
            {
                rho = triple;
                binding = 8 + j;
            }
        }

        return m + (binding < 8 ? OnMidLine(s, binding, rho) : Meet(s, binding - 8, rho));
    }

    /// <summary>
    /// The centre with the eight supports in one 256-bit vector: every candidate's value, and
    /// the centre for every possible binding candidate (four mid-lines, eight triples), lane by
    /// lane with the scalar path's arithmetic; the binding one is then picked. No branch and no
    /// memory round trip: which candidate binds changes from one pose to the next.
    /// </summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    internal static Vector2 OfVector(in Vector4 min, in Vector4 max)
    {
        Vector2 m = BoxCentre(min, max, out Vector4 above, out Vector4 below);

        // s = (above.X, above.Z, above.Y, below.W, below.X, below.Z, below.Y, above.W); rₖ: s turned by k lanes.
        var s = Vector256.Shuffle(Vector256.Create(above.AsVector128(), below.AsVector128()), Vector256.Create(0, 2, 1, 7, 4, 6, 5, 3));
        var r1 = Vector256.Shuffle(s, Vector256.Create(1, 2, 3, 4, 5, 6, 7, 0));
        var r2 = Vector256.Shuffle(s, Vector256.Create(2, 3, 4, 5, 6, 7, 0, 1));
        var r3 = Vector256.Shuffle(s, Vector256.Create(3, 4, 5, 6, 7, 0, 1, 2));
        var r4 = Vector256.Shuffle(s, Vector256.Create(4, 5, 6, 7, 0, 1, 2, 3));
        var r5 = Vector256.Shuffle(s, Vector256.Create(5, 6, 7, 0, 1, 2, 3, 4));
        var r6 = Vector256.Shuffle(s, Vector256.Create(6, 7, 0, 1, 2, 3, 4, 5));
        var r7 = Vector256.Shuffle(s, Vector256.Create(7, 0, 1, 2, 3, 4, 5, 6));
        var half = Vector256.Create(Half);
        var root2 = Vector256.Create(Root2);

        // Candidates: widths in lanes 0..3 (4..7 repeat them), triples in lanes 0..7.
        var widths = Vector256.Create(0.5f) * (s + r4);
        var triples = ((half * s) + r3 + (half * r6)) * Vector256.Create(TripleScale);
        var best = Vector256.MaxNative(widths, triples);
        best = Vector256.MaxNative(best, Vector256.Shuffle(best, Vector256.Create(4, 5, 6, 7, 0, 1, 2, 3)));
        best = Vector256.MaxNative(best, Vector256.Shuffle(best, Vector256.Create(2, 3, 0, 1, 6, 7, 4, 5)));
        var rho = Vector256.MaxNative(best, Vector256.Shuffle(best, Vector256.Create(1, 0, 3, 2, 5, 4, 7, 6)));
        uint found = (Vector256.Equals(widths, rho).ExtractMostSignificantBits() & 0xF)
            | (Vector256.Equals(triples, rho).ExtractMostSignificantBits() << 8);
        int binding = BitOperations.TrailingZeroCount(found);

        // Mid-line centres, lane k (lanes 0..3 are used).
        var mid = Vector256.Create(0.5f) * (s - r4);
        var slant = mid * half;
        var tLo = Vector256.MaxNative(Vector256.MaxNative((r1 - rho - slant) * root2, r2 - rho), (r3 - rho + slant) * root2);
        var tHi = Vector256.MinNative(Vector256.MinNative((rho - r5 - slant) * root2, rho - r6), (rho - r7 + slant) * root2);
        var t = Vector256.Create(0.5f) * (tLo + tHi);
        var cos = Vector256.Create(1f, Half, 0f, -Half, -1f, -Half, 0f, Half);
        var sin = Vector256.Create(0f, Half, 1f, Half, 0f, -Half, -1f, -Half);
        var midX = (mid * cos) - (t * sin);
        var midY = (mid * sin) + (t * cos);

        // Triple centres, lane j: e_j·c = s_j − ρ and e_{j+3}·c = s_{j+3} − ρ.
        var b1 = s - rho;
        var b2 = r3 - rho;
        var cos3 = Vector256.Create(-Half, -1f, -Half, 0f, Half, 1f, Half, 0f);
        var sin3 = Vector256.Create(Half, 0f, -Half, -1f, -Half, 0f, Half, 1f);
        var meetX = ((b1 * sin3) - (sin * b2)) * root2;
        var meetY = ((cos * b2) - (b1 * cos3)) * root2;

        var onMidLine = Vector256.Create(binding < 8 ? -1 : 0).AsSingle();
        var x = Vector256.ConditionalSelect(onMidLine, midX, meetX);
        var y = Vector256.ConditionalSelect(onMidLine, midY, meetY);
        return m + new Vector2(x.GetElement(binding & 7), y.GetElement(binding & 7));
    }

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    private static Vector2 BoxCentre(in Vector4 min, in Vector4 max, out Vector4 above, out Vector4 below)
    {
        Vector2 m = new(0.5f * (min.X + max.X), 0.5f * (min.Y + max.Y));
        Vector4 pm = new(m.X, m.Y, (m.X + m.Y) * Half, (m.X - m.Y) * Half);
        above = max - pm;
        below = pm - min;
        return m;
    }

    // The binding width is along e_k (k < 4): c = mid·e_k + t·e_{k+2}. Each other constraint
    // eᵢ·c ≥ sᵢ − ρ with eᵢ·e_{k+2} = cos((i − k − 2)·45°) ∈ {√½, 1, √½, −√½, −1, −√½} bounds t
    // from below (i = k+1..k+3) or above (i = k+5..k+7); t is the middle of what is left.
    private static Vector2 OnMidLine(ReadOnlySpan<float> s, int k, float rho)
    {
        float mid = 0.5f * (s[k] - s[k + 4]), slant = mid * Half;
        float tLo = Max(Max((s[k + 1] - rho - slant) * Root2, s[k + 2] - rho), (s[k + 3] - rho + slant) * Root2);
        float tHi = Min(Min((rho - s[(k + 5) & 7] - slant) * Root2, rho - s[(k + 6) & 7]), (rho - s[(k + 7) & 7] + slant) * Root2);
        float t = 0.5f * (tLo + tHi);
        float cos = Cos[k], sin = Sin[k];
        return new Vector2((mid * cos) - (t * sin), (mid * sin) + (t * cos));
    }

    // The binding triple j, j+3, j+6: the point where e_j·c = s_j − ρ and e_{j+3}·c = s_{j+3} − ρ (determinant sin 135° = √½).
    private static Vector2 Meet(ReadOnlySpan<float> s, int j, float rho)
    {
        int i = (j + 3) & 7;
        float b1 = s[j] - rho, b2 = s[i] - rho;
        return new Vector2(((b1 * Sin[i]) - (Sin[j] * b2)) * Root2, ((Cos[j] * b2) - (b1 * Cos[i])) * Root2);
    }

    // The plain maximum and minimum of two finite numbers, as the vector path takes them.
    private static float Max(float a, float b) => a > b ? a : b;

    private static float Min(float a, float b) => a < b ? a : b;
}
