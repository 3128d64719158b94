namespace URWPGSim2D.Collision.Pool;

/// <summary>
/// The pool: a rectangle of <see cref="Length"/> × <see cref="Width"/> mm centred on the
/// origin (X along the length, Z across), with a goal at each X end and, optionally, the four
/// goal blocks that fill the corners beside the goals.
/// </summary>
/// <remarks>
/// A goal is the region between the two goal blocks of one side: |z| ≤ <see cref="GoalWidth"/>/2
/// and within <see cref="GoalDepth"/> of the end wall, which is its back wall. The goal blocks
/// are static boxes X ∈ [L/2 − 150, L/2] (mirrored for the left side) × Z ∈ [W/2 side, ±200],
/// exact (the original rounded them through screen pixels to 1348), each with its outer
/// circle for the paper's two-layer test. The walls are the four field edges; the goal mouths
/// are open, so a ball can enter a goal up to its back wall.
/// </remarks>
public sealed partial class Field
{
    /// <summary>Width of each goal mouth, mm (the goal spans |z| ≤ 200).</summary>
    public const float GoalWidth = 400f;

    /// <summary>Depth of each goal (and X extent of each goal block), mm.</summary>
    public const float GoalDepth = 150f;

    private readonly Aabb[] _goalBlocks;
    private readonly Circle[] _goalBlockOuterCircles;
    private readonly Segment[] _walls;

    /// <summary>Creates a pool, validating its size.</summary>
    /// <param name="length">Extent along X, mm (default 3000; 4500 is also used). Must exceed 2 · <see cref="GoalDepth"/>.</param>
    /// <param name="width">Extent along Z, mm (default 2000; 3000 is also used). Must exceed <see cref="GoalWidth"/>.</param>
    /// <param name="goalBlocks">Whether the four goal blocks are present.</param>
    /// <exception cref="ArgumentException">A size is not finite or too small (the message names the parameter and the value).</exception>
    public Field(float length = 3000f, float width = 2000f, bool goalBlocks = true)
    {
        Guard.Positive(length, nameof(length));
        Guard.Positive(width, nameof(width));
        if (!(length > 2f * GoalDepth))
        {
            throw new ArgumentException($"must exceed twice the goal depth ({2f * GoalDepth} mm), got {length}", nameof(length));
        }

        if (!(width > GoalWidth))
        {
            throw new ArgumentException($"must exceed the goal width ({GoalWidth} mm), got {width}", nameof(width));
        }

        Length = length;
        Width = width;
        HalfLength = 0.5f * length;
        HalfWidth = 0.5f * width;
        Bounds = new Aabb(new Vector2(-HalfLength, -HalfWidth), new Vector2(HalfLength, HalfWidth));
        _goalBlocks = goalBlocks ? BuildGoalBlocks(HalfLength, HalfWidth) : [];
        _goalBlockOuterCircles = Array.ConvertAll(_goalBlocks, block => block.BoundingCircle);
        Vector2 topLeft = new(-HalfLength, -HalfWidth), topRight = new(HalfLength, -HalfWidth);
        Vector2 bottomRight = new(HalfLength, HalfWidth), bottomLeft = new(-HalfLength, HalfWidth);
        _walls = [new(topLeft, topRight), new(topRight, bottomRight), new(bottomRight, bottomLeft), new(bottomLeft, topLeft)];
    }

    /// <summary>Extent along X, mm.</summary>
    public float Length { get; }

    /// <summary>Extent along Z, mm.</summary>
    public float Width { get; }

    /// <summary>The field rectangle [−L/2, L/2] × [−W/2, W/2], mm.</summary>
    public Aabb Bounds { get; }

    /// <summary>
    /// The goal blocks (empty without them). Index i is the original's goalBlock(i+1):
    /// 0 left top (x &lt; 0, z &lt; 0), 1 right top, 2 left bottom, 3 right bottom.
    /// </summary>
    public ReadOnlySpan<Aabb> GoalBlocks => _goalBlocks;

    /// <summary>The outer circle of each goal block (centred on it, through its corners), same order as <see cref="GoalBlocks"/>.</summary>
    public ReadOnlySpan<Circle> GoalBlockOuterCircles => _goalBlockOuterCircles;

    /// <summary>The four field edges, numbered as in the original: 0 top (z = −W/2), 1 right (x = L/2), 2 bottom (z = W/2), 3 left (x = −L/2).</summary>
    public ReadOnlySpan<Segment> Walls => _walls;

    private float HalfLength { get; }

    private float HalfWidth { get; }

    private static Aabb[] BuildGoalBlocks(float halfLength, float halfWidth)
    {
        float inner = halfLength - GoalDepth, mouth = 0.5f * GoalWidth;
        return
        [
            new(new Vector2(-halfLength, -halfWidth), new Vector2(-inner, -mouth)),
            new(new Vector2(inner, -halfWidth), new Vector2(halfLength, -mouth)),
            new(new Vector2(-halfLength, mouth), new Vector2(-inner, halfWidth)),
            new(new Vector2(inner, mouth), new Vector2(halfLength, halfWidth)),
        ];
    }
}
