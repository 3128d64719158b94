using System;
using System.Numerics;
using URWPGSim2D.Collision.Shapes;

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

    // 1 / (1 + √2): the weights of a triple are √½, 1, √½.
    private const float TripleScale = 0.41421356237309505f;

    // eⱼ for j = 0..7 (arrays, not span literals: those allocate on every use in debug builds).
    private static readonly float[] Cos = [1f, Half, 0f, -Half, -1f, -Half, 0f, Half];

    private static readonly float[] Sin = [0f, Half, 1f, Half, 0f, -Half, -1f, -Half];

    /// <summary>The centre for slabs minᵢ ≤ p·aᵢ ≤ maxᵢ on the four 8-DOP axes (a non-empty set).</summary>
    public static Vector2 Of(Vector4 min, Vector4 max)
    {
        // Relative to the box centre, so that large coordinates do not cost precision.
        Vector2 m = new(0.5f * (min.X + max.X), 0.5f * (min.Y + max.Y));
        Vector4 pm = KDop8.Project(m);
        Vector4 lo = min - pm, hi = max - pm;
        Span<float> s = stackalloc float[8];
        s[0] = hi.X;
        s[1] = hi.Z;
        s[2] = hi.Y;
        s[3] = -lo.W;
        s[4] = -lo.X;
        s[5] = -lo.Z;
        s[6] = -lo.Y;
        s[7] = hi.W;

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

        Vector2 c = binding < 8 ? OnMidLine(s, binding, rho) : Meet(s, binding - 8, rho);
        return m + c;
    }

    // The binding width is along e_k: c = mid·e_k + t·e_{k+2}; each other constraint eᵢ·c ≥ sᵢ − ρ bounds t.
    private static Vector2 OnMidLine(ReadOnlySpan<float> s, int k, float rho)
    {
        float mid = 0.5f * (s[k] - s[k + 4]);
        float tLo = float.NegativeInfinity, tHi = float.PositiveInfinity;
        for (int step = 1; step < 8; step++)
        {
            if (step == 4)
            {
                continue;
            }

            int i = (k + step) & 7;
            float along = Cos[(step - 2) & 7];
            float bound = (s[i] - rho - (mid * Cos[step])) / along;
            if (along > 0f)
            {
                tLo = MathF.Max(tLo, bound);
            }
            else
            {
                tHi = MathF.Min(tHi, bound);
            }
        }

        float t = 0.5f * (tLo + tHi);
        int p = (k + 2) & 7;
        return new Vector2((mid * Cos[k]) + (t * Cos[p]), (mid * Sin[k]) + (t * Sin[p]));
    }

    // The binding triple j, j+3, j+6: the point where e_j·c = s_j − ρ and e_{j+3}·c = s_{j+3} − ρ (determinant sin 135° = √½).
    private static Vector2 Meet(ReadOnlySpan<float> s, int j, float rho)
    {
        int i = (j + 3) & 7;
        float b1 = s[j] - rho, b2 = s[i] - rho;
        float x = ((b1 * Sin[i]) - (Sin[j] * b2)) / Half;
        float y = ((Cos[j] * b2) - (b1 * Cos[i])) / Half;
        return new Vector2(x, y);
    }
}
