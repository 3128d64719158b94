namespace URWPGSim2D.Collision.Motion;

/// <summary>
/// The rigid motion that carries a fish's collision model (built at pose P₀, θ₀) onto the fish
/// (now at P, θ with the same joint angles): x ↦ P + R(θ − θ₀)·(x − P₀). Within a cycle the joints
/// do not change, so a partner moved into the model's frame by the inverse motion meets the model
/// exactly as it would meet a model rebuilt at the new pose — without rebuilding it.
/// </summary>
internal readonly struct RigidFrame
{
    private readonly Vector2 _from;
    private readonly Vector2 _to;
    private readonly float _cos;
    private readonly float _sin;

    /// <summary>The motion from the model's pose (<paramref name="from"/>, <paramref name="fromHeading"/>) to (<paramref name="to"/>, <paramref name="toHeading"/>).</summary>
    public RigidFrame(Vector2 from, float fromHeading, Vector2 to, float toHeading)
    {
        _from = from;
        _to = to;
        float turn = toHeading - fromHeading;
        if (turn == 0f)
        {
            _cos = 1f;
            _sin = 0f;
        }
        else
        {
            (_sin, _cos) = MathF.SinCos(turn);
        }

        Turn = turn;
        IsIdentity = turn == 0f && from == to;
        IsTranslation = turn == 0f;
    }

    private RigidFrame(in RigidFrame turned, Vector2 from, Vector2 to)
    {
        _from = from;
        _to = to;
        _cos = turned._cos;
        _sin = turned._sin;
        Turn = turned.Turn;
        IsIdentity = turned.IsTranslation && from == to;
        IsTranslation = turned.IsTranslation;
    }

    /// <summary>The turn θ − θ₀, rad, as the constructor computed it.</summary>
    public float Turn { get; }

    /// <summary>
    /// The motion with this one's turn (its sine and cosine reused, so bit for bit what the
    /// constructor gives for the same turn) from <paramref name="from"/> to <paramref name="to"/>.
    /// Only for a frame the constructor built: a default frame has no turn to reuse.
    /// </summary>
    public RigidFrame Moved(Vector2 from, Vector2 to) => new(this, from, to);

    /// <summary>True when the model is exactly at the fish's pose.</summary>
    public bool IsIdentity { get; }

    /// <summary>True when the fish has not turned since the model was built.</summary>
    public bool IsTranslation { get; }

    /// <summary>
    /// The rigid motion from the model frame of <paramref name="b"/> into the model frame of
    /// <paramref name="a"/> (through the world): x ↦ R·x + t, R given as (cos, sin).
    /// </summary>
    public static void Between(in RigidFrame b, in RigidFrame a, out Vector2 rotation, out Vector2 translation)
    {
        float cos = (b._cos * a._cos) + (b._sin * a._sin);
        float sin = (b._sin * a._cos) - (b._cos * a._sin);
        rotation = new Vector2(cos, sin);
        Vector2 turnedFrom = new((b._from.X * cos) - (b._from.Y * sin), (b._from.X * sin) + (b._from.Y * cos));
        translation = a._from + a.RotateBack(b._to - a._to) - turnedFrom;
    }

    /// <summary>A model-frame point in the world.</summary>
    public Vector2 ToWorld(Vector2 model) => _to + Rotate(model - _from);

    /// <summary>
    /// Model-frame points in the world: <see cref="ToWorld(Vector2)"/> of each, with the same bits
    /// (four points per 256-bit vector where the hardware has them, each lane doing the same
    /// products and sums). <paramref name="world"/> must not overlap <paramref name="model"/>.
    /// </summary>
    public void ToWorld(ReadOnlySpan<Vector2> model, Span<Vector2> world) =>
        RigidTransform.PlaceAbout(model, world, _from, _to, new Vector2(_cos, _sin));

    /// <summary>A world point in the model's frame.</summary>
    public Vector2 ToModel(Vector2 world) => _from + RotateBack(world - _to);

    /// <summary>A model-frame direction in the world.</summary>
    public Vector2 Rotate(Vector2 v) => new((v.X * _cos) - (v.Y * _sin), (v.X * _sin) + (v.Y * _cos));

    /// <summary>A world direction in the model's frame.</summary>
    public Vector2 RotateBack(Vector2 v) => new((v.X * _cos) + (v.Y * _sin), (-v.X * _sin) + (v.Y * _cos));
}
