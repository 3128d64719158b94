namespace URWPGSim2D.Engine.Simulation;

/// <summary>
/// The contacts resolved in the current cycle (cleared each cycle; the buffer is sized for the
/// world up front, four contacts per moving body and at least 128, and grows by doubling only
/// when a cycle has more contacts than that) and the match's running counts by kind.
/// </summary>
public sealed class ContactLog
{
    private ContactRecord[] _records;
    private readonly long[] _byKind = new long[7];

    /// <summary>A log with room for a busy cycle of <paramref name="movers"/> moving bodies (four contacts each, at least 128).</summary>
    public ContactLog(int movers = 0)
    {
        _records = new ContactRecord[Math.Max(128, 4 * movers)];
    }

    /// <summary>This cycle's contacts in resolution order.</summary>
    public ReadOnlySpan<ContactRecord> Cycle => _records.AsSpan(0, Count);

    /// <summary>Number of contacts this cycle.</summary>
    public int Count { get; private set; }

    /// <summary>Contacts of the whole match by <see cref="ContactKind"/>.</summary>
    public ReadOnlySpan<long> ByKind => _byKind;

    /// <summary>Starts a new cycle.</summary>
    public void BeginCycle() => Count = 0;

    /// <summary>Forgets every contact and count, as a new log (its buffer kept): a match restarted in place.</summary>
    internal void Restart()
    {
        Count = 0;
        System.Array.Clear(_byKind);
    }

    /// <summary>Records one contact.</summary>
    public void Add(in ContactRecord record, ContactKind kind)
    {
        if (Count == _records.Length)
        {
            Array.Resize(ref _records, _records.Length * 2);
        }

        _records[Count++] = record;
        _byKind[(int)kind]++;
    }
}
