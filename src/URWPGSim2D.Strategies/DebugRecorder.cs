namespace URWPGSim2D.Strategies;

/// <summary>
/// Collects one team's debug drawings (<see cref="DebugDraw"/>) during one call of its strategy, up to
/// <see cref="MaxShapes"/> shapes and <see cref="MaxTextChars"/> characters of text per cycle (what is
/// over is dropped and counted). The server makes one per team when drawings are recorded and makes it
/// the current one on the thread that calls the strategy (<see cref="Enter"/>); without one, every
/// drawing call returns at once and costs nothing.
/// </summary>
public sealed class DebugRecorder
{
    /// <summary>Shapes kept per team and cycle.</summary>
    public const int MaxShapes = 128;

    /// <summary>Characters of text kept per team and cycle (all texts together; a text over it is cut).</summary>
    public const int MaxTextChars = 4096;

    [ThreadStatic]
    private static DebugRecorder? t_current;

    private readonly DebugShape[] _shapes = new DebugShape[MaxShapes];
    private int[] _fish = [];
    private int _textChars;

    /// <summary>The recorder of the strategy call running on this thread, or null (drawings are off).</summary>
    public static DebugRecorder? Current => t_current;

    /// <summary>Shapes recorded since <see cref="Clear"/>.</summary>
    public int Count { get; private set; }

    /// <summary>Shapes dropped since <see cref="Clear"/> because the cycle's bound was reached.</summary>
    public int Dropped { get; private set; }

    /// <summary>The shapes recorded since <see cref="Clear"/>.</summary>
    public ReadOnlySpan<DebugShape> Shapes => _shapes.AsSpan(0, Count);

    /// <summary>Forgets the shapes of the last cycle.</summary>
    public void Clear()
    {
        Array.Clear(_shapes, 0, Count);
        Count = 0;
        Dropped = 0;
        _textChars = 0;
    }

    /// <summary>Makes this the current recorder of the calling thread for a call that controls <paramref name="fish"/>, cleared.</summary>
    /// <param name="fish">Indices of the fish the strategy controls, in its decisions' order.</param>
    public void Enter(int[] fish)
    {
        ArgumentNullException.ThrowIfNull(fish);
        _fish = fish;
        Clear();
        t_current = this;
    }

    /// <summary>Ends the call: the calling thread has no current recorder any more.</summary>
    public static void Exit() => t_current = null;

    /// <summary>The fish index of the team's <paramref name="ordinal"/>-th fish (in decisions' order), or −1 (the team) when out of range.</summary>
    /// <param name="ordinal">The fish's place among the team's decisions.</param>
    public int FishOfOrdinal(int ordinal) => (uint)ordinal < (uint)_fish.Length ? _fish[ordinal] : -1;

    /// <summary>Adds a shape; a <paramref name="fish"/> the strategy does not control makes it the team's; non-finite coordinates drop it.</summary>
    /// <param name="kind">What the shape is.</param>
    /// <param name="fish">The fish it belongs to, or −1 for the team.</param>
    /// <param name="a">Its point, start or centre, mm.</param>
    /// <param name="b">Its end (a line), mm.</param>
    /// <param name="radius">Its radius (a circle), mm.</param>
    /// <param name="rgb">Colour 0xRRGGBB, or −1 for the team's colour.</param>
    /// <param name="text">Its text (a text), or null.</param>
    public void Add(DebugShapeKind kind, int fish, Vector2 a, Vector2 b, float radius, int rgb, string? text)
    {
        if (!float.IsFinite(a.X) || !float.IsFinite(a.Y) || !float.IsFinite(b.X) || !float.IsFinite(b.Y) || !float.IsFinite(radius))
        {
            Dropped++;
            return;
        }

        if (Count == MaxShapes)
        {
            Dropped++;
            return;
        }

        if (text is not null)
        {
            int room = MaxTextChars - _textChars;
            if (room <= 0)
            {
                Dropped++;
                return;
            }

            if (text.Length > room)
            {
                text = text[..room];
            }

            _textChars += text.Length;
        }

        if (fish >= 0 && Array.IndexOf(_fish, fish) < 0)
        {
            fish = -1;
        }

        _shapes[Count++] = new DebugShape(kind, fish < 0 ? -1 : fish, a, b, MathF.Max(radius, 0f), rgb < 0 ? -1 : rgb & 0xFFFFFF, text);
    }

    /// <summary>Adds the shapes of <paramref name="other"/> (a call that ran on another thread) to this recorder, within the bounds.</summary>
    /// <param name="other">The other call's recorder.</param>
    public void AddFrom(DebugRecorder other)
    {
        ArgumentNullException.ThrowIfNull(other);
        Dropped += other.Dropped;
        foreach (ref readonly var s in other.Shapes)
        {
            AddShape(s);
        }
    }

    /// <summary>Adds one shape read back (from the protocol or another recorder), within the bounds.</summary>
    /// <param name="s">The shape.</param>
    public void AddShape(in DebugShape s) => Add(s.Kind, s.Fish, s.A, s.B, s.Radius, s.Rgb, s.Text);

    /// <summary>Sets the fish the team controls (for a recorder filled from the protocol) and clears it.</summary>
    /// <param name="fish">Indices of the fish the team controls, in its decisions' order.</param>
    public void Reset(int[] fish)
    {
        ArgumentNullException.ThrowIfNull(fish);
        _fish = fish;
        Clear();
    }
}
