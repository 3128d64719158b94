using URWPGSim2D.Engine.Matches;
using URWPGSim2D.Engine.Simulation;

namespace URWPGSim2D.Server.Cli;

/// <summary>The end-of-match summary printed by <c>run</c>.</summary>
internal static class MatchSummary
{
    private static readonly string[] KindNames = ["fish-fish", "fish-ball", "fish-obstacle", "fish-border", "ball-ball", "ball-obstacle", "ball-border"];

    /// <summary>Formats the summary of a match played as fast as it goes (several lines, ending in a newline).</summary>
    /// <param name="match">The match.</param>
    /// <param name="wall">The wall time it took.</param>
    public static string Format(Match match, TimeSpan wall)
    {
        var c = CultureInfo.InvariantCulture;
        var stats = match.Statistics;
        double simulated = stats.Cycles * 0.1;
        double seconds = Math.Max(wall.TotalSeconds, 1e-9);
        return Format(match, string.Create(c, $"match: {stats.Cycles} cycles, {simulated:0.0} s simulated in {wall.TotalMilliseconds:0.0} ms wall time ({simulated / seconds:0}x real time, {wall.TotalMilliseconds * 1000.0 / Math.Max(1, stats.Cycles):0.00} us per cycle), seed {match.Seed}\n"));
    }

    /// <summary>
    /// Formats the summary of a match played live (<c>run --live</c>): its real-time figure is the
    /// match's own wall time, pauses included, and the time spent computing is given per cycle.
    /// </summary>
    /// <param name="match">The match.</param>
    /// <param name="played">Its wall time from the start of its first cycle to the end of its last.</param>
    /// <param name="computing">The part of it spent computing cycles.</param>
    public static string FormatLive(Match match, TimeSpan played, TimeSpan computing)
    {
        var c = CultureInfo.InvariantCulture;
        var stats = match.Statistics;
        double simulated = stats.Cycles * 0.1;
        string pace = played > TimeSpan.Zero ? string.Create(c, $"{simulated / played.TotalSeconds:0.0}x real time, ") : string.Empty;
        return Format(match, string.Create(c, $"match: {stats.Cycles} cycles, {simulated:0.0} s simulated, played live in {played.TotalSeconds:0.0} s wall time ({pace}{computing.TotalMilliseconds * 1000.0 / Math.Max(1, stats.Cycles):0.00} us of computing per cycle), seed {match.Seed}\n"));
    }

    // The summary under its first line.
    private static string Format(Match match, string first)
    {
        var c = CultureInfo.InvariantCulture;
        var stats = match.Statistics;
        var s = new StringBuilder(first);
        if (match.Referee is { } referee)
        {
            ItemSummary.Append(s, match, referee);
        }
        else
        {
            s.Append(c, $"goals: team 0 ({match.TeamLabel(0)}) {match.Rules.Scores[0]}, team 1 ({match.TeamLabel(1)}) {match.Rules.Scores[1]}\n");
        }

        s.Append("contacts:");
        var byKind = match.Contacts.ByKind;
        for (int k = 0; k < byKind.Length; k++)
        {
            s.Append(c, $" {KindNames[k]} {byKind[k]}").Append(k + 1 < byKind.Length ? "," : "\n");
        }

        s.Append(c, $"sub-steps: {stats.SubSteps} (at most {stats.MostSubSteps} in one cycle), contact events: {stats.Events}\n");
        s.Append(c, $"largest leftover overlap: {stats.LargestLeftoverOverlap:0.000} mm");
        s.Append(stats.LargestLeftoverCycle > 0 ? string.Create(c, $" (cycle {stats.LargestLeftoverCycle})\n") : "\n");
        s.Append("strategy faults:");
        bool any = false;
        foreach (var slot in match.Caller().Slots)
        {
            if (slot.Faults == 0)
            {
                continue;
            }

            any = true;
            s.Append(c, $"\n  team {slot.Team} ({slot.Label}): {slot.Exceptions} exceptions, {slot.Timeouts} timeouts, {slot.BadAnswers} bad answers");
            s.Append(slot switch
            {
                { IdleFromCycle: > 0, Crashes: 0 } => string.Create(c, $", out of time in cycle {slot.IdleFromCycle}; its fish kept their last decisions until then and stopped after"),
                { Crashes: 0 } => "; its fish kept their last decisions",
                { CreationFault: not null } => ", strategy not created; its fish stopped for the whole match",
                _ => string.Create(c, $", strategy host ended in cycle {slot.EndedInCycle}; its fish kept their last decisions until then and stopped after"),
            });
            s.Append(c, $"; first: {slot.FirstFault}");
        }

        s.Append(any ? "\n" : " none\n");
        AppendTime(s, match.Caller());
        return s.ToString();
    }

    // The time banks of the teams whose strategies are timed: one line, and a line for each team that drew on its bank.
    private static void AppendTime(StringBuilder s, Hosting.StrategyCaller strategies)
    {
        var c = CultureInfo.InvariantCulture;
        bool timed = false, drawn = false;
        foreach (var slot in strategies.Slots)
        {
            timed |= slot.Bank is not null;
            drawn |= slot.Bank is { LateCalls: > 0 };
        }

        if (!timed)
        {
            return;
        }

        s.Append(c, $"strategy time: {strategies.TimeoutMs} ms of CPU time a call, a time bank of {strategies.TimeBank.TotalSeconds:0.0##} s a team for late calls:");
        if (!drawn)
        {
            s.Append(" none drawn\n");
            return;
        }

        foreach (var slot in strategies.Slots)
        {
            if (slot.Bank is { LateCalls: > 0 } bank)
            {
                s.Append(c, $"\n  team {slot.Team} ({slot.Label}): {bank.LateCalls} late {(bank.LateCalls == 1 ? "call" : "calls")}, {bank.Used.TotalSeconds:0.000} s drawn{(bank.Spent ? ", bank spent" : "")}, slowest call {bank.Slowest.TotalMilliseconds:0} ms");
            }
        }

        s.Append('\n');
    }
}
