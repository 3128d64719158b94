namespace URWPGSim2D.Collision.Fish;

/// <summary>
/// Where each leaf lives in the fish model's packed buffers, and which rigid frame carries it.
/// The body group (both pectoral fins and the body) comes first, then the tail group.
/// </summary>
internal static class FishLeafLayout
{
    /// <summary>Number of leaf polygons.</summary>
    public const int LeafCount = 8;

    /// <summary>Total number of leaf vertices (4 + 5 + 4 + 4 + 4 + 4 + 3 + 3).</summary>
    public const int VertexCount = 31;

    /// <summary>Leaves [0, BodyGroupEnd) form the body group; the rest form the tail group.</summary>
    public const int BodyGroupEnd = 3;

    /// <summary>First vertex of the tail group in the packed buffer.</summary>
    public const int TailGroupFirstVertex = 13;

    /// <summary>Number of rigid frames: the body, then tail segments 1, 2, 3.</summary>
    public const int FrameCount = 4;

    private static ReadOnlySpan<byte> FrameStarts => [0, 13, 17, 21, 31];

    private static ReadOnlySpan<byte> Offsets => [0, 4, 9, 13, 17, 21, 25, 28];

    private static ReadOnlySpan<byte> Counts => [4, 5, 4, 4, 4, 4, 3, 3];

    // Frame 0 = body (origin P, angle θ); frame i = tail segment i (origin Sᵢ, angle θ + φᵢ).
    private static ReadOnlySpan<byte> Frames => [0, 0, 0, 1, 2, 3, 3, 3];

    /// <summary>Index of the leaf's first vertex in the packed buffers.</summary>
    public static int Offset(int leaf) => Offsets[leaf];

    /// <summary>Number of vertices of the leaf.</summary>
    public static int Count(int leaf) => Counts[leaf];

    /// <summary>The rigid frame (0 body, 1..3 tail segment) the leaf is fixed in.</summary>
    public static int Frame(int leaf) => Frames[leaf];

    /// <summary>First packed vertex carried by a frame (frame 4: the end of the buffer); each frame's vertices are contiguous.</summary>
    public static int FrameStart(int frame) => FrameStarts[frame];

    /// <summary>Checks a part value and returns it as a leaf index.</summary>
    /// <exception cref="ArgumentException">The value is not one of the eight parts.</exception>
    public static int Index(FishPart part, string paramName)
    {
        int leaf = (int)part;
        if ((uint)leaf >= LeafCount)
        {
            throw new ArgumentException($"must be one of the eight fish parts, got {leaf}", paramName);
        }

        return leaf;
    }
}
