using System.Threading;

namespace URWPGSim2D.Collision.Fish;

/// <summary>
/// Templates shared by size. A template never changes, so every model of one size can share one:
/// a crowd's fish then read the same few hundred bytes when their models are posed, instead of each
/// its own copy. Holds the last <see cref="Capacity"/> sizes asked for (a new size beyond them
/// replaces the oldest; models keep theirs); safe to use from any thread.
/// </summary>
internal sealed class FishTemplates
{
    /// <summary>How many sizes are shared at once.</summary>
    public const int Capacity = 16;

    private readonly Lock _gate = new();
    private FishTemplate[] _shared = [];
    private int _replace;

    /// <summary>The templates every fish model shares.</summary>
    public static FishTemplates Shared { get; } = new();

    /// <summary>The template of fish of <paramref name="size"/> (a validated size).</summary>
    public FishTemplate For(in FishSize size)
    {
        foreach (FishTemplate known in Volatile.Read(ref _shared))
        {
            if (known.Size == size)
            {
                return known;
            }
        }

        var made = new FishTemplate(size);
        lock (_gate)
        {
            FishTemplate[] now = _shared;
            foreach (FishTemplate known in now)
            {
                if (known.Size == size)
                {
                    return known;
                }
            }

            FishTemplate[] next = now.Length < Capacity ? [.. now, made] : [.. now];
            if (now.Length == Capacity)
            {
                next[_replace] = made;
                _replace = (_replace + 1) % Capacity;
            }

            Volatile.Write(ref _shared, next);
        }

        return made;
    }
}
