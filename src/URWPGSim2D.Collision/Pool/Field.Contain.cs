using System.Runtime.InteropServices;

namespace URWPGSim2D.Collision.Pool;

/// <content>
/// The in-pool test of the paper: from a shape's extreme coordinates decide whether it lies
/// wholly inside the field rectangle (touching a wall counts as inside) and, if not, return
/// the wall contact whose MTV brings it back inside.
/// </content>
/// <remarks>
/// The MTV corrects each axis on which the shape sticks out: (L/2 − maxX) or (−L/2 − minX),
/// and the same in Z, so in a corner it moves the shape off both walls at once. The normal is
/// the MTV's direction (toward the inside); the action point is the shape's point farthest
/// along −normal, clamped onto the field. A shape larger than the field on an axis is centred
/// on that axis instead (it cannot fit). Goal mouths are open: a shape in a goal is inside as
/// long as it does not cross the back wall (the goal blocks are separate static obstacles).
/// </remarks>
public sealed partial class Field
{
    /// <summary>Whether a circle lies wholly inside the pool; if not, the contact that brings it back.</summary>
    /// <param name="circle">The circle (e.g. the ball), moved by the MTV.</param>
    /// <returns><see cref="CollisionDetectionResult.None"/> when inside, else the wall contact.</returns>
    public CollisionDetectionResult Contain(in Circle circle)
    {
        Vector2 c = circle.Center, r = new(circle.Radius);
        if (!Correction(c - r, c + r, out Vector2 mtv))
        {
            return CollisionDetectionResult.None;
        }

        Vector2 normal = Direction(mtv);
        return Result(mtv, normal, c - normal * circle.Radius);
    }

    /// <summary>Whether a point set (e.g. a polygon's vertices) lies wholly inside the pool; if not, the contact that brings it back.</summary>
    /// <param name="points">At least one point, mm.</param>
    /// <returns><see cref="CollisionDetectionResult.None"/> when inside, else the wall contact (its MTV moves the points).</returns>
    /// <exception cref="ArgumentException"><paramref name="points"/> is empty or has a coordinate that is not finite.</exception>
    public CollisionDetectionResult Contain(ReadOnlySpan<Vector2> points)
    {
        if (points.IsEmpty)
        {
            throw new ArgumentException("needs at least one point, got none", nameof(points));
        }

        if (!Extremes(points, out Vector2 min, out Vector2 max))
        {
            // Name the first point that is not finite.
            for (int i = 0; i < points.Length; i++)
            {
                Vector2 p = points[i];
                if (!float.IsFinite(p.X) || !float.IsFinite(p.Y))
                {
                    throw new ArgumentException($"points[{i}] must have finite coordinates, got [{p.X}, {p.Y}]", nameof(points));
                }
            }
        }

        if (!Correction(min, max, out Vector2 mtv))
        {
            return CollisionDetectionResult.None;
        }

        Vector2 normal = Direction(mtv);
        return Result(mtv, normal, Support(points, -normal, out _));
    }

    /// <summary>Whether a fish lies wholly inside the pool, from its extreme coordinates (<see cref="FishModel.Bounds"/>).</summary>
    /// <param name="fish">The fish, moved by the MTV.</param>
    /// <returns><see cref="FishContact.None"/> when inside, else the wall contact with <see cref="FishContact.PartA"/> = the leaf that sticks out the most along the MTV.</returns>
    /// <exception cref="ArgumentNullException"><paramref name="fish"/> is null.</exception>
    public FishContact Contain(FishModel fish)
    {
        ArgumentNullException.ThrowIfNull(fish);
        Aabb box = fish.Bounds;
        if (!Correction(box.Min, box.Max, out Vector2 mtv))
        {
            return FishContact.None;
        }

        Vector2 normal = Direction(mtv);
        FishPart deepest = FishPart.LeftPectoral;
        Vector2 point = default;
        float best = float.NegativeInfinity;
        for (var part = FishPart.LeftPectoral; part <= FishPart.RightCaudal; part++)
        {
            Vector2 p = Support(fish.GetLeaf(part), -normal, out float reach);
            if (reach > best)
            {
                best = reach;
                point = p;
                deepest = part;
            }
        }

        return new FishContact(Result(mtv, normal, point), deepest, null);
    }

    /// <summary>Whether a ball lies wholly inside a goal: wholly past the goal line and within the mouth.</summary>
    /// <param name="ball">The ball.</param>
    /// <param name="side">−1 for the left goal (x &lt; 0), +1 for the right goal, 0 when in neither.</param>
    /// <returns>True when |z| + r ≤ <see cref="GoalWidth"/>/2 and x − r ≥ L/2 − <see cref="GoalDepth"/> (right) or x + r ≤ −L/2 + <see cref="GoalDepth"/> (left).</returns>
    public bool IsInGoal(in Circle ball, out int side)
    {
        Vector2 c = ball.Center;
        float r = ball.Radius, line = HalfLength - GoalDepth;
        side = MathF.Abs(c.Y) + r > 0.5f * GoalWidth ? 0
            : c.X - r >= line ? 1
            : c.X + r <= -line ? -1
            : 0;
        return side != 0;
    }

    // The least and greatest coordinates of the points (at least one), four points per 256-bit
    // vector where the hardware has them (a minimum or maximum is one of its inputs, and -0 counts
    // below +0 on every path, so the order of the points changes no bit); false when a coordinate
    // is not finite.
    private static bool Extremes(ReadOnlySpan<Vector2> points, out Vector2 min, out Vector2 max)
    {
        if (Vector256.IsHardwareAccelerated && points.Length >= 4)
        {
            ref float first = ref Unsafe.As<Vector2, float>(ref MemoryMarshal.GetReference(points));
            var low = Vector256.LoadUnsafe(ref first);
            var high = low;
            var finite = Vector256<float>.AllBitsSet;

            // The last block overlaps the one before (a repeat changes no minimum or maximum).
            for (int at = 0; ; at += 4)
            {
                at = Math.Min(at, points.Length - 4);
                var p = Vector256.LoadUnsafe(ref first, (nuint)(2 * at));
                low = Vector256.Min(low, p);
                high = Vector256.Max(high, p);
                finite &= Vector256.Equals(p - p, Vector256<float>.Zero); // inf − inf and NaN − NaN are NaN
                if (at == points.Length - 4)
                {
                    break;
                }
            }

            var lo = Vector128.Min(low.GetLower(), low.GetUpper());
            var hi = Vector128.Max(high.GetLower(), high.GetUpper());
            lo = Vector128.Min(lo, Vector128.Shuffle(lo, Vector128.Create(2, 3, 0, 1)));
            hi = Vector128.Max(hi, Vector128.Shuffle(hi, Vector128.Create(2, 3, 0, 1)));
            min = new Vector2(lo.GetElement(0), lo.GetElement(1));
            max = new Vector2(hi.GetElement(0), hi.GetElement(1));
            return finite == Vector256<float>.AllBitsSet;
        }

        min = points[0];
        max = points[0];
        foreach (Vector2 p in points)
        {
            if (!float.IsFinite(p.X) || !float.IsFinite(p.Y))
            {
                return false;
            }

            min = Vector2.Min(min, p);
            max = Vector2.Max(max, p);
        }

        return true;
    }

    // The per-axis translation that brings the box [min, max] inside the field; false when none is needed.
    private bool Correction(Vector2 min, Vector2 max, out Vector2 mtv)
    {
        mtv = new Vector2(Axis(min.X, max.X, HalfLength), Axis(min.Y, max.Y, HalfWidth));
        return mtv != Vector2.Zero || max.X - min.X > Length || max.Y - min.Y > Width;
    }

    private static float Axis(float lo, float hi, float half)
    {
        if (hi - lo > 2f * half)
        {
            return -0.5f * (lo + hi);
        }

        return lo < -half ? -half - lo : hi > half ? half - hi : 0f;
    }

    private static Vector2 Direction(Vector2 mtv)
    {
        float length = mtv.Length();
        return length > 0f ? mtv / length : Vector2.UnitX;
    }

    private CollisionDetectionResult Result(Vector2 mtv, Vector2 normal, Vector2 extreme)
    {
        Vector2 onField = Vector2.Clamp(extreme, new Vector2(-HalfLength, -HalfWidth), new Vector2(HalfLength, HalfWidth));
        return CollisionDetectionResult.FromPlane(normal, mtv.Length(), onField);
    }

    private static Vector2 Support(ReadOnlySpan<Vector2> points, Vector2 direction, out float reach)
    {
        Vector2 best = points[0];
        reach = Vector2.Dot(best, direction);
        for (int i = 1; i < points.Length; i++)
        {
            float d = Vector2.Dot(points[i], direction);
            if (d > reach)
            {
                reach = d;
                best = points[i];
            }
        }

        return best;
    }
}
