using System.Threading.Tasks;

namespace URWPGSim2D.Viewer;

/// <summary>
/// What the live view has sent since the match (re)started: an append-only list of ready-made
/// Server-Sent-Events messages, read by every viewer connection at its own pace. Publishing
/// never waits for a viewer, so a slow or vanished viewer cannot stop or slow the match. A
/// restart clears the list and bumps <see cref="Generation"/>; readers then start over.
/// </summary>
public sealed class LiveFeed
{
    private readonly object _gate = new();
    private readonly List<byte[]> _messages = new(4096);
    private TaskCompletionSource _changed = NewSignal();

    /// <summary>Incremented by every <see cref="Reset"/>.</summary>
    public int Generation { get; private set; }

    /// <summary>Messages published in the current generation.</summary>
    public int Count
    {
        get
        {
            lock (_gate)
            {
                return _messages.Count;
            }
        }
    }

    /// <summary>Completes at the next publish or reset (take it before <see cref="Read"/> so no change is missed).</summary>
    public Task Changed
    {
        get
        {
            lock (_gate)
            {
                return _changed.Task;
            }
        }
    }

    /// <summary>Starts a new generation with no messages.</summary>
    public void Reset()
    {
        lock (_gate)
        {
            _messages.Clear();
            Generation++;
            Pulse();
        }
    }

    /// <summary>Appends a message (a complete SSE message, ending in a blank line).</summary>
    public void Publish(byte[] message)
    {
        lock (_gate)
        {
            _messages.Add(message);
            Pulse();
        }
    }

    /// <summary>
    /// Copies up to <paramref name="max"/> messages from <paramref name="next"/> on into
    /// <paramref name="into"/> and advances <paramref name="next"/>. When <paramref name="generation"/>
    /// is not the current one, reading restarts at 0. Returns the current generation.
    /// </summary>
    public int Read(int generation, ref int next, List<byte[]> into, int max)
    {
        lock (_gate)
        {
            if (generation != Generation)
            {
                next = 0;
            }

            int end = next + System.Math.Min(max, _messages.Count - next); // next + max may overflow
            for (int i = next; i < end; i++)
            {
                into.Add(_messages[i]);
            }

            next = end;
            return Generation;
        }
    }

    private static TaskCompletionSource NewSignal() => new(TaskCreationOptions.RunContinuationsAsynchronously);

    private void Pulse()
    {
        var done = _changed;
        _changed = NewSignal();
        done.TrySetResult();
    }
}
