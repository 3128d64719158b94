namespace URWPGSim2D.Collision.Fish;

/// <summary>
/// The tail group and root circles of a fish in its body frame (origin P, axis along the
/// heading). The fish's shape in that frame depends on the three joint angles only, so the
/// circles are recomputed only when a joint changes — within a step the joints stay put unless they turn over it
/// while position and heading move through sub-steps and contact searches — and the model
/// moves them rigidly to each pose, as it moves the body group circle.
/// </summary>
/// <remarks>
/// The answer is a function of the joint angles alone (compared bit for bit), whatever poses came
/// before. Each circle is centred on the smallest fixed-axis octagon around its points (see
/// <see cref="OctagonCentre"/>) and reaches the farthest one, so it is at most 1/cos 22.5° times
/// the minimum enclosing circle.
/// </remarks>
internal sealed class FishShapeCircles
{
    private readonly FishTemplate _template;
    private readonly Vector2[] _points = new Vector2[FishLeafLayout.VertexCount];
    private readonly Vector4 _bodyMin;
    private readonly Vector4 _bodyMax;
    private bool _valid;
    private int _joint1, _joint2, _joint3;

    public FishShapeCircles(FishTemplate template)
    {
        _template = template;
        int tail = FishLeafLayout.TailGroupFirstVertex;
        template.Vertices[..tail].CopyTo(_points);
        FloatSlabs.Of(_points.AsSpan(0, tail), out _bodyMin, out _bodyMax);
    }

    /// <summary>The tail group's circle in the body frame (centre relative to P, x along the heading).</summary>
    public Circle Tail { get; private set; }

    /// <summary>The whole fish's circle in the body frame.</summary>
    public Circle Root { get; private set; }

    /// <summary>The farthest any vertex lies from P at these joint angles (bounded by the root circle), mm.</summary>
    public float Reach { get; private set; }

    /// <summary>Brings the circles up to date for the joint angles φ1..φ3 (a no-op when they are unchanged).</summary>
    public void Update(float joint1, float joint2, float joint3)
    {
        int b1 = BitConverter.SingleToInt32Bits(joint1), b2 = BitConverter.SingleToInt32Bits(joint2), b3 = BitConverter.SingleToInt32Bits(joint3);
        if (_valid && b1 == _joint1 && b2 == _joint2 && b3 == _joint3)
        {
            return;
        }

        // The tail frames in the body frame: origin (−L/2, 0), then back along each segment.
        var size = _template.Size;
        Vector2 r1 = Direction(joint1), r2 = Direction(joint2), r3 = Direction(joint3);
        Vector2 o1 = new(-_template.HalfLength, 0f);
        Vector2 o2 = o1 - size.Joint1 * r1;
        Vector2 o3 = o2 - size.Joint2 * r2;
        Place(1, o1, r1);
        Place(2, o2, r2);
        Place(3, o3, r3);

        var tailPoints = _points.AsSpan(FishLeafLayout.TailGroupFirstVertex);
        FloatSlabs.Of(tailPoints, out Vector4 tailMin, out Vector4 tailMax);
        Vector2 tailCentre = OctagonCentre.Of(tailMin, tailMax);
        Vector2 rootCentre = OctagonCentre.Of(Vector4.Min(_bodyMin, tailMin), Vector4.Max(_bodyMax, tailMax));
        Tail = Circle.Bounding(tailCentre, MathF.Sqrt(EnclosingCircle.FarthestSquared(tailPoints, tailCentre)));
        Root = Circle.Bounding(rootCentre, MathF.Sqrt(EnclosingCircle.FarthestSquared(_points, rootCentre)));
        Reach = Root.Center.Length() + Root.Radius;
        (_joint1, _joint2, _joint3, _valid) = (b1, b2, b3, true);
    }

    private static Vector2 Direction(float angle)
    {
        (float sin, float cos) = MathF.SinCos(angle);
        return new Vector2(cos, sin);
    }

    private void Place(int frame, Vector2 origin, Vector2 rotation)
    {
        int start = FishLeafLayout.FrameStart(frame), count = FishLeafLayout.FrameStart(frame + 1) - start;
        RigidTransform.Place(_template.Vertices.Slice(start, count), _points.AsSpan(start, count), origin, rotation);
    }
}
