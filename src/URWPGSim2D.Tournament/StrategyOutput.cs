using System.Text;
using URWPGSim2D.Engine.Matches;
using URWPGSim2D.Engine.Trace;
using URWPGSim2D.Hosting;

namespace URWPGSim2D.Tournament;

/// <summary>
/// What one match's strategies printed, per team, and each team's slowest call: kept apart from the
/// match's result and its replay page, for the team alone (a ladder's team sees its own). Each
/// cycle's output is kept as <c>cycle N: TEXT</c> (the strategy log of a cycle is bounded), and at
/// most <see cref="MaxChars"/> characters per team and match: what is over is counted, not kept.
/// </summary>
public sealed class StrategyOutput
{
    /// <summary>Characters kept per team and match.</summary>
    public const int MaxChars = 64 * 1024;

    private static readonly byte[] LogProperty = Encoding.UTF8.GetBytes(",\"log\":[");

    private readonly StringBuilder[] _text;
    private readonly int[] _dropped;
    private readonly double?[] _slowestMs;

    /// <summary>An empty output of a match of <paramref name="teams"/> teams.</summary>
    /// <param name="teams">The teams of the match.</param>
    public StrategyOutput(int teams)
    {
        ArgumentOutOfRangeException.ThrowIfLessThan(teams, 1);
        _text = [.. Enumerable.Range(0, teams).Select(_ => new StringBuilder())];
        _dropped = new int[teams];
        _slowestMs = new double?[teams];
    }

    /// <summary>The teams.</summary>
    public int Teams => _text.Length;

    /// <summary>What team <paramref name="team"/>'s strategy printed, with a note of what was dropped.</summary>
    /// <param name="team">The team (0-based, as it played).</param>
    public string Text(int team) => _dropped[team] == 0
        ? _text[team].ToString()
        : _text[team].ToString() + string.Create(CultureInfo.InvariantCulture, $"… {_dropped[team]} more characters dropped (at most {MaxChars} a match)\n");

    /// <summary>Team <paramref name="team"/>'s slowest call, ms, when measured (strategies in a host or on their own thread), else null.</summary>
    /// <param name="team">The team (0-based, as it played).</param>
    public double? SlowestMs(int team) => _slowestMs[team];

    /// <summary>Adds what each strategy printed in the cycle just played.</summary>
    internal void AddCycle(Match match)
    {
        int cycle = match.World.Cycle;
        foreach (var slot in match.Caller().Slots)
        {
            if (slot.Log is not { } log || (log.Length == 0 && log.Dropped == 0) || slot.Team >= _text.Length)
            {
                continue;
            }

            string line = string.Create(CultureInfo.InvariantCulture, $"cycle {cycle}: ") + log.ToString().TrimEnd('\n') + "\n";
            var text = _text[slot.Team];
            int room = MaxChars - text.Length;
            if (line.Length > room)
            {
                _dropped[slot.Team] += line.Length - Math.Max(room, 0);
                line = line[..Math.Max(room, 0)];
            }

            text.Append(line);
        }
    }

    /// <summary>Takes each team's slowest call at the end of the match.</summary>
    internal void End(Match match)
    {
        foreach (var slot in match.Caller().Slots)
        {
            if (slot.Team < _slowestMs.Length && slot.Bank is { } bank)
            {
                double ms = bank.Slowest.TotalMilliseconds;
                _slowestMs[slot.Team] = _slowestMs[slot.Team] is { } known ? Math.Max(known, ms) : ms;
            }
        }
    }

    /// <summary>
    /// A trace sink that passes each line on without its strategy log (<c>"log"</c>, the line's last
    /// property): a replay recorded beside this output shows no team's printed text.
    /// </summary>
    internal sealed class WithoutLogs(ITraceSink inner) : ITraceSink
    {
        private byte[] _buffer = new byte[4096];

        /// <inheritdoc/>
        public void WriteLine(ReadOnlySpan<byte> line)
        {
            // Inside a JSON string every quote is escaped, so the first `,"log":[` is the property itself.
            int at = line.IndexOf(LogProperty);
            if (at < 0)
            {
                inner.WriteLine(line);
                return;
            }

            if (_buffer.Length < at + 1)
            {
                _buffer = new byte[Math.Max(at + 1, _buffer.Length * 2)];
            }

            line[..at].CopyTo(_buffer);
            _buffer[at] = (byte)'}';
            inner.WriteLine(_buffer.AsSpan(0, at + 1));
        }
    }
}
