using System.Linq;

namespace URWPGSim2D.Hosting;

/// <summary>
/// Pre-started strategy hosts: a host's runtime takes most of its start (the .NET runtime, the
/// server's code, its first compilation by the JIT), so hosts are started ahead, sandboxed and
/// waiting (<see cref="HostProcess.StartWaiting"/>), and a match's compiled strategy is handed to
/// one (<see cref="HostProcess.HandOver"/>). Each waiting host is a fresh process that has run no
/// strategy, so every match still starts from fresh strategy state. Hosts wait per strategy (its
/// sandbox binds the strategy's files, as a host started for it), settings and sandbox: a team loaded
/// for hosts reserves one (<see cref="Reserve"/>); a host taken after the
/// reserved ones have all been taken once (the second match of a batch on) is
/// replaced at once, for the next match. A tournament's entrant, which plays many matches, is
/// reserved to be kept waiting: every host of it taken is replaced at once, so each of its matches
/// gets a host that has warmed up during the match before. Waiting hosts end with the program.
/// </summary>
public static class HostPool
{
    /// <summary>The most hosts that wait for one kind of settings.</summary>
    public const int MostWaiting = 4;

    private static readonly object Gate = new();
    private static readonly Dictionary<(PreparedStrategy Strategy, HostSettings Settings, bool Sandbox), Kind> Kinds = [];
    private static int _hooked;

    /// <summary>Reserves a waiting host for a team of a coming match, started now in the background.</summary>
    /// <param name="strategy">The team's strategy.</param>
    /// <param name="settings">The hosts' settings.</param>
    /// <param name="sandbox">Whether hosts use bubblewrap.</param>
    /// <param name="keep">Whether every host of the strategy taken is replaced at once (a tournament's entrant), not only those taken beyond the reserved ones.</param>
    public static void Reserve(PreparedStrategy strategy, HostSettings settings, bool sandbox, bool keep = false)
    {
        Kind kind;
        lock (Gate)
        {
            kind = Of(strategy, settings, sandbox);
            kind.Keep |= keep;
            if (kind.Target >= MostWaiting)
            {
                return;
            }

            kind.Target++;
            kind.Starting++;
        }

        StartOne(strategy, settings, sandbox, kind);
    }

    /// <summary>A host waiting for <paramref name="strategy"/>, or null when none waits (the caller starts one as before).</summary>
    /// <param name="strategy">The team's strategy.</param>
    /// <param name="settings">The hosts' settings.</param>
    /// <param name="sandbox">Whether hosts use bubblewrap.</param>
    public static HostProcess? Take(PreparedStrategy strategy, HostSettings settings, bool sandbox)
    {
        HostProcess? host = null;
        Kind kind;
        bool refill;
        lock (Gate)
        {
            kind = Of(strategy, settings, sandbox);
            while (kind.Waiting.Count == 0 && kind.Starting > 0)
            {
                Monitor.Wait(Gate, 2000); // one is being started (the process starts in milliseconds; it warms up on its own)
            }

            while (kind.Waiting.Count > 0 && host is null)
            {
                var next = kind.Waiting.Dequeue();
                if (next.HasExited)
                {
                    ThreadPool.QueueUserWorkItem(_ => next.Dispose());
                }
                else
                {
                    host = next;
                }
            }

            kind.Taken++;
            refill = (kind.Keep || kind.Taken > kind.Target) && kind.Waiting.Count + kind.Starting < kind.Target;
            if (refill)
            {
                kind.Starting++;
            }
        }

        if (refill)
        {
            StartOne(strategy, settings, sandbox, kind);
        }

        return host;
    }

    /// <summary>
    /// Ends the hosts waiting for <paramref name="strategy"/> (under any settings) and stops keeping
    /// any for it: its next match starts its own host, unless it is reserved again. A service that
    /// readies many strategies keeps hosts waiting only for those that play soon.
    /// </summary>
    /// <param name="strategy">The team's strategy.</param>
    /// <returns>How many waiting hosts were ended.</returns>
    public static int Release(PreparedStrategy strategy)
    {
        var ended = new List<HostProcess>();
        lock (Gate)
        {
            foreach (var key in Kinds.Keys.Where(k => k.Strategy.Equals(strategy)).ToList())
            {
                var kind = Kinds[key];
                kind.Released = true;
                ended.AddRange(kind.Waiting);
                kind.Waiting.Clear();
                Kinds.Remove(key);
            }

            Monitor.PulseAll(Gate);
        }

        foreach (var host in ended)
        {
            host.Dispose();
        }

        return ended.Count;
    }

    /// <summary>The process ids of the hosts waiting for <paramref name="strategy"/> now.</summary>
    /// <param name="strategy">The team's strategy.</param>
    public static IReadOnlyList<int> WaitingFor(PreparedStrategy strategy)
    {
        lock (Gate)
        {
            return [.. Kinds.Where(k => k.Key.Strategy.Equals(strategy)).SelectMany(k => k.Value.Waiting).Select(h => h.ProcessId)];
        }
    }

    /// <summary>Ends every waiting host (at the program's end).</summary>
    public static void Clear()
    {
        var all = new List<HostProcess>();
        lock (Gate)
        {
            foreach (var kind in Kinds.Values)
            {
                all.AddRange(kind.Waiting);
                kind.Waiting.Clear();
                kind.Target = 0;
                kind.Taken = 0;
            }
        }

        foreach (var host in all)
        {
            host.Dispose();
        }
    }

    private static Kind Of(PreparedStrategy strategy, HostSettings settings, bool sandbox)
    {
        if (!Kinds.TryGetValue((strategy, settings, sandbox), out var kind))
        {
            kind = new Kind();
            Kinds[(strategy, settings, sandbox)] = kind;
        }

        if (Interlocked.Exchange(ref _hooked, 1) == 0)
        {
            AppDomain.CurrentDomain.ProcessExit += (_, _) => Clear();
        }

        return kind;
    }

    // Starts a waiting host on a thread of the pool; one that cannot start is dropped.
    private static void StartOne(PreparedStrategy strategy, HostSettings settings, bool sandbox, Kind kind) => ThreadPool.QueueUserWorkItem(_ =>
    {
        HostProcess? host = null;
        try
        {
            host = HostProcess.StartWaiting(strategy.ReadOnly, sandbox, settings);
        }
        catch (Exception e) when (e is System.ComponentModel.Win32Exception or InvalidOperationException or System.IO.IOException or UnauthorizedAccessException)
        {
            // no waiting host this time: the match starts its own
        }

        bool released;
        lock (Gate)
        {
            kind.Starting--;
            released = kind.Released;
            if (host is not null && !released)
            {
                kind.Waiting.Enqueue(host);
            }

            Monitor.PulseAll(Gate);
        }

        if (released)
        {
            host?.Dispose(); // its strategy was released while this host started
        }
    });

    private sealed class Kind
    {
        public Queue<HostProcess> Waiting { get; } = new();

        public int Target { get; set; }

        public int Starting { get; set; }

        public int Taken { get; set; }

        public bool Keep { get; set; }

        public bool Released { get; set; }
    }
}
