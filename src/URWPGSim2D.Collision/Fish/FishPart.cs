namespace URWPGSim2D.Collision.Fish;

/// <summary>
/// The eight convex leaf polygons of the multi-joint fish model, in the order of the
/// URWPGSim2D reference (the underlying value is the leaf index 0..7).
/// </summary>
public enum FishPart
{
    /// <summary>The left pectoral fin (on the fish's left, −Z at heading 0): a quadrilateral beside the body.</summary>
    LeftPectoral,

    /// <summary>The body rectangle with the triangular head in front: a pentagon.</summary>
    Body,

    /// <summary>The right pectoral fin: the left fin mirrored across the body axis.</summary>
    RightPectoral,

    /// <summary>The first tail segment (joint 1), a tapered quadrilateral behind the body.</summary>
    Tail1,

    /// <summary>The second tail segment (joint 2).</summary>
    Tail2,

    /// <summary>The third tail segment (joint 3).</summary>
    Tail3,

    /// <summary>The left lobe of the caudal fin: a triangle rigid in tail segment 3's frame.</summary>
    LeftCaudal,

    /// <summary>The right lobe of the caudal fin: a triangle rigid in tail segment 3's frame.</summary>
    RightCaudal,
}
