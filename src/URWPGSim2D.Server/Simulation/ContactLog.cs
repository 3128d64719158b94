using System;

namespace URWPGSim2D.Server.Simulation;

/// <summary>
/// The contacts resolved in the current cycle (cleared each cycle; the buffer grows by doubling
/// only when a cycle has more contacts than ever before) and the match's running counts by kind.
/// </summary>
internal sealed class ContactLog
{
    private ContactRecord[] _records = new ContactRecord[1024];
    private readonly long[] _byKind = new long[7];

    /// <summary>This cycle's contacts in resolution order.</summary>
    public ReadOnlySpan<ContactRecord> Cycle => _records.AsSpan(0, Count);

    /// <summary>Number of contacts this cycle.</summary>
    public int Count { get; private set; }

    /// <summary>Contacts of the whole match by <see cref="ContactKind"/>.</summary>
    public ReadOnlySpan<long> ByKind => _byKind;

    /// <summary>Starts a new cycle.</summary>
    public void BeginCycle() => Count = 0;

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
