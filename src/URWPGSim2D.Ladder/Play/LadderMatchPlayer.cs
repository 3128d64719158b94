using System;
using System.Collections.Concurrent;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using System.Text;
using URWPGSim2D.Engine.Items;
using URWPGSim2D.Hosting;
using URWPGSim2D.Tournament;

namespace URWPGSim2D.Ladder.Play;

/// <summary>
/// Plays a ladder match as <c>tournament</c> plays one (<see cref="TournamentMatchPlayer"/>): each
/// side's entrant readied once per process (<see cref="EntrantLoader"/>: sources compiled in the
/// compiler's child process, hosts pre-started) and a fresh team strategy per match, in a fresh
/// sandboxed strategy host; a side that cannot be loaded forfeits; a match that fails inside the
/// server is a forfeit of the side at fault (<see cref="TournamentRunner.Failed"/>). The result is
/// the tournament's record, as one line of a tournament result file.
/// </summary>
internal sealed class LadderMatchPlayer
{
    private readonly CompetitionItem _item;
    private readonly HostSettings _hostSettings;
    private readonly int _strategyTimeoutMs;
    private readonly ConcurrentDictionary<(long Team, long Submission), Lazy<EntrantLoader>> _loaders = new();
    private readonly LinkedList<(long Team, long Submission)> _warm = new(); // most recently used first
    private readonly object _warmGate = new();

    /// <param name="item">The ladder's item.</param>
    /// <param name="hostSettings">How strategies run.</param>
    /// <param name="strategyTimeoutMs">The time limit of a call.</param>
    /// <param name="warmLimit">The most submissions that keep a started strategy host waiting.</param>
    public LadderMatchPlayer(CompetitionItem item, HostSettings hostSettings, int strategyTimeoutMs, int warmLimit)
    {
        ArgumentOutOfRangeException.ThrowIfLessThan(warmLimit, 2);
        _item = item;
        _hostSettings = hostSettings;
        _strategyTimeoutMs = strategyTimeoutMs;
        WarmLimit = warmLimit;
    }

    /// <summary>The most submissions that keep a started strategy host waiting: those used last (checked or played).</summary>
    public int WarmLimit { get; }

    /// <summary>
    /// The readied entrant of a team's submission (0: its house strategy), compiled once. It keeps a
    /// started host waiting for its next match while it is among the <see cref="WarmLimit"/> used last;
    /// the hosts of the one used longest ago end, and it reserves one again when it is used again.
    /// </summary>
    public EntrantLoader Loader(long team, long submission, Entrant entrant)
    {
        bool readied = false;
        var key = (team, submission);
        var loader = _loaders.GetOrAdd(key, _ => new Lazy<EntrantLoader>(() =>
        {
            readied = true; // readying reserves its host
            return new EntrantLoader([entrant], _hostSettings);
        })).Value;
        if (!loader.AnyHosted)
        {
            return loader; // a built-in strategy: no host to keep
        }

        var cold = new List<EntrantLoader>();
        bool reserve;
        lock (_warmGate)
        {
            reserve = !_warm.Remove(key) && !readied;
            _warm.AddFirst(key);
            while (_warm.Count > WarmLimit)
            {
                cold.Add(_loaders[_warm.Last!.Value].Value);
                _warm.RemoveLast();
            }
        }

        if (reserve)
        {
            loader.Reserve();
        }

        foreach (var c in cold)
        {
            c.Release();
        }

        return loader;
    }

    /// <summary>Plays match <paramref name="index"/> and returns its record.</summary>
    /// <param name="index">The match's id.</param>
    /// <param name="seed">Its seed.</param>
    /// <param name="cycles">Its length.</param>
    /// <param name="sides">Per side, the team, the submission (0: house) and the entrant.</param>
    /// <param name="replayPage">Where its replay page goes.</param>
    /// <param name="output">Where what each side's strategy printed and its slowest call go (kept out of the replay page), or null.</param>
    public TournamentRecord Play(int index, ulong seed, int cycles, IReadOnlyList<(long Team, long Submission, Entrant Entrant)> sides, string? replayPage, StrategyOutput? output = null)
    {
        var names = sides.Select(s => s.Entrant.Name).ToArray();
        var match = new ScheduledMatch(index, seed, [.. Enumerable.Range(0, sides.Count)]);
        var teams = new TeamStrategy?[Math.Max(2, sides.Count)];
        var forfeits = new List<int>();
        var reasons = new List<string>();
        var loaders = new EntrantLoader[sides.Count];
        for (int t = 0; t < sides.Count; t++)
        {
            loaders[t] = Loader(sides[t].Team, sides[t].Submission, sides[t].Entrant);
            string? error = loaders[t].Errors[0];
            if (error is null)
            {
                try
                {
                    teams[t] = loaders[t].Create(0);
                }
                catch (StrategyLoadException e)
                {
                    error = EntrantLoader.Reason(e);
                }
            }

            if (error is not null)
            {
                forfeits.Add(t);
                reasons.Add(error);
            }
        }

        if (forfeits.Count > 0)
        {
            return new TournamentRecord(index, seed, names, null, forfeits, reasons);
        }

        try
        {
            var result = TournamentMatchPlayer.Play(_item, match, teams, cycles, _strategyTimeoutMs, replayPage, output);
            return new TournamentRecord(index, seed, names, result, [], []);
        }
        catch (Exception e) when (e is not OutOfMemoryException)
        {
            var header = new TournamentHeader(_item.Slug, [.. sides.Select(s => s.Entrant)], 1, seed, cycles, _strategyTimeoutMs, 1);
            return new TournamentRunner(_item, header, loaders[0], null).Failed(match, e);
        }
    }

    /// <summary>A record as one line of a tournament result file (no line feed).</summary>
    public static string Line(TournamentRecord record)
    {
        using var stream = new MemoryStream();
        TournamentFile.WriteRecord(stream, record);
        return Encoding.UTF8.GetString(stream.ToArray()).TrimEnd('\n');
    }
}
