using URWPGSim2D.Hosting;
using URWPGSim2D.Engine.Items;
using URWPGSim2D.Engine.Matches;
using URWPGSim2D.Engine.Scenario;
using URWPGSim2D.Engine.Simulation;

namespace URWPGSim2D.Tournament;

/// <summary>
/// <c>tournament --check</c>: a pre-flight of each entrant before the real run, which a teacher can
/// send back to the class: whether it compiles and loads, and one match of at most a minute against
/// <c>idle</c> (the entrant on team 0, <c>idle</c> on every other team) with its faults, its slowest call
/// and the most memory its strategy host held.
/// </summary>
public static class EntrantCheck
{
    /// <summary>Cycles of a check match at most: one minute.</summary>
    public const int MostCycles = 600;

    /// <summary>One entrant's line.</summary>
    /// <param name="Name">The entrant.</param>
    /// <param name="Error">Why it cannot be loaded, or null.</param>
    /// <param name="Exceptions">Calls that threw in the check match.</param>
    /// <param name="Timeouts">Calls that missed their deadline.</param>
    /// <param name="BadAnswers">Calls that answered badly.</param>
    /// <param name="HostEnds">Its strategy host ended before the match did (0 or 1).</param>
    /// <param name="SlowestMs">Its slowest call, ms, when measured (loaded strategies), else null.</param>
    /// <param name="Score">Its score in the check match.</param>
    /// <param name="FirstFault">Its first fault (<c>cycle N: message</c>), or null.</param>
    /// <param name="PeakMemoryBytes">The most memory its strategy host's sandbox held at once, bytes (runtime included), when measured (a host in a control group), else null.</param>
    public sealed record Line(string Name, string? Error, int Exceptions, int Timeouts, int BadAnswers, int HostEnds, double? SlowestMs, int Score, string? FirstFault, long? PeakMemoryBytes = null)
    {
        /// <summary>Whether the entrant is ready: it loads and played without a fault.</summary>
        public bool Ready => Error is null && Exceptions + Timeouts + BadAnswers + HostEnds == 0;
    }

    /// <summary>Checks every entrant (one after the other).</summary>
    /// <param name="item">The item.</param>
    /// <param name="entrants">The entrants and, last, <c>idle</c> (the opponent).</param>
    /// <param name="loader">The entrants readied (the same list).</param>
    /// <param name="cycles">The tournament's match length (the check plays at most <see cref="MostCycles"/>).</param>
    /// <param name="seed">The seed.</param>
    /// <param name="strategyTimeoutMs">The deadline per call.</param>
    public static List<Line> Run(CompetitionItem item, IReadOnlyList<Entrant> entrants, EntrantLoader loader, int cycles, ulong seed, int strategyTimeoutMs)
    {
        int idle = entrants.Count - 1;
        var lines = new List<Line>(idle);
        for (int e = 0; e < idle; e++)
        {
            if (loader.Errors[e] is { } error)
            {
                lines.Add(new Line(entrants[e].Name, error, 0, 0, 0, 0, null, 0, null));
                continue;
            }

            var teams = new TeamStrategy?[Math.Max(2, item.TeamCount)];
            teams[0] = loader.Create(e);
            for (int t = 1; t < teams.Length; t++)
            {
                teams[t] = loader.Create(idle);
            }

            var settings = new MatchSettings(item.CreateScenario(seed), Math.Min(cycles, MostCycles), seed, Noise: null, teams, strategyTimeoutMs);
            using var loop = new MatchLoop(settings.Build(), settings.Cycles);
            loop.Play();
            var mine = loop.Match.Caller().Slots.Where(s => s.Team == 0).ToList();
            double? slowest = mine.Select(s => s.Bank?.Slowest.TotalMilliseconds).Where(x => x is not null).DefaultIfEmpty(null).Max();
            long? memory = mine.Select(s => s.PeakMemoryBytes).Where(x => x is not null).DefaultIfEmpty(null).Max();
            lines.Add(new Line(
                entrants[e].Name, null, mine.Sum(s => s.Exceptions), mine.Sum(s => s.Timeouts), mine.Sum(s => s.BadAnswers), mine.Sum(s => s.Crashes),
                slowest, loop.Match.Rules.Scores[0], mine.Select(s => s.FirstFault).FirstOrDefault(f => f is not null), memory));
        }

        return lines;
    }

    /// <summary>The table as the terminal shows it.</summary>
    public static string Format(IReadOnlyList<Line> lines, CompetitionItem item, int cycles, ulong seed)
    {
        int width = Math.Max(7, lines.Max(l => l.Name.Length));
        var t = new StringBuilder();
        t.Append(string.Create(CultureInfo.InvariantCulture, $"check: {item.Slug}, {lines.Count} entrants, each in one {Math.Min(cycles, MostCycles)}-cycle match against idle (seed {seed})\n"));
        t.Append(string.Create(CultureInfo.InvariantCulture, $"{"entrant".PadRight(width)}  {"ready",-5}  {"exceptions",10}  {"timeouts",8}  {"bad answers",11}  {"host ends",9}  {"slowest call",12}  {"memory",8}  {"score",5}  first fault or why not loaded\n"));
        foreach (var l in lines)
        {
            string slowest = l.SlowestMs is { } ms ? string.Create(CultureInfo.InvariantCulture, $"{ms:0} ms") : "-";
            string memory = l.PeakMemoryBytes is { } bytes ? string.Create(CultureInfo.InvariantCulture, $"{bytes / (1024 * 1024)} MiB") : "-";
            string note = l.Error is { } error ? "not loaded: " + error : l.FirstFault ?? "-";
            t.Append(string.Create(CultureInfo.InvariantCulture,
                $"{l.Name.PadRight(width)}  {(l.Ready ? "yes" : "no"),-5}  {l.Exceptions,10}  {l.Timeouts,8}  {l.BadAnswers,11}  {l.HostEnds,9}  {slowest,12}  {memory,8}  {l.Score,5}  {Engine.Messages.MessageText.Escape(StandingsText.Line(note))}\n"));
        }

        int ready = lines.Count(l => l.Ready);
        t.Append(string.Create(CultureInfo.InvariantCulture, $"{ready} of {lines.Count} entrants ready\n"));
        return t.ToString();
    }
}
