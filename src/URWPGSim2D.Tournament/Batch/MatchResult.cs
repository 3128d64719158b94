using URWPGSim2D.Hosting;
using URWPGSim2D.Engine.Matches;
using URWPGSim2D.Engine.Simulation;

namespace URWPGSim2D.Tournament.Batch;

/// <summary>
/// What one match of a batch produced: a line of the result file. Only simulation results (no
/// wall time), so the same match gives the same result on any machine, core count or shard.
/// </summary>
/// <param name="Index">Match number in the batch, 0 … N − 1.</param>
/// <param name="Seed">Its seed (the batch's first seed + index).</param>
/// <param name="Cycles">Cycles played.</param>
/// <param name="Goals0">Goals of team 0.</param>
/// <param name="Goals1">Goals of team 1.</param>
/// <param name="Contacts">Contacts by kind, in the summary's order (fish-fish … ball-border).</param>
/// <param name="SubSteps">Sample times over all cycles.</param>
/// <param name="MostSubSteps">Most sample times in one cycle.</param>
/// <param name="Events">Contact events.</param>
/// <param name="LeftoverOverlap">Deepest overlap left at the end of any cycle, mm.</param>
/// <param name="LeftoverCycle">The cycle that left it (0 if none).</param>
/// <param name="StrategyFaults">Exceptions and time-outs of all strategies.</param>
/// <param name="Item">The competition item's slug, or null for the plain goal rules.</param>
/// <param name="Scores">The item's score per team (null without an item).</param>
/// <param name="Winner">The item's winning team, or −1 (a draw, no winner, or no item).</param>
/// <param name="Rule">The rule that decided the item's result (null without an item).</param>
/// <param name="Faults">Per team, the faults of each strategy that faulted (null or empty: none).</param>
/// <param name="Failed">Why the match failed inside the server (its other fields are then zero), or null.</param>
public sealed record MatchResult(
    int Index, ulong Seed, int Cycles, int Goals0, int Goals1, long[] Contacts, long SubSteps,
    int MostSubSteps, long Events, float LeftoverOverlap, int LeftoverCycle, int StrategyFaults,
    string? Item = null, int[]? Scores = null, int Winner = -1, string? Rule = null, TeamFaults[]? Faults = null,
    string? Failed = null)
{
    /// <summary>The line of a match that failed inside the server: nothing played, the reason kept.</summary>
    public static MatchResult FailedMatch(int index, ulong seed, Exception e) =>
        new(index, seed, 0, 0, 0, new long[ContactNames.Length], 0, 0, 0, 0f, 0, 0,
            Failed: Engine.Messages.MessageText.Escape($"{e.GetType().Name}: {e.Message}"));

    /// <summary>Contact kinds as the result file and the summaries name them.</summary>
    public static readonly string[] ContactNames = ["fish-fish", "fish-ball", "fish-obstacle", "fish-border", "ball-ball", "ball-obstacle", "ball-border"];

    /// <summary>The result of a finished match.</summary>
    public static MatchResult Of(int index, ulong seed, Match match)
    {
        var stats = match.Statistics;
        var referee = match.Referee;
        int[] scores = match.Rules.Scores;
        int goals0 = scores[0];
        int goals1 = scores.Length > 1 ? scores[1] : 0;
        var outcome = referee?.Outcome;
        return new MatchResult(
            index, seed, stats.Cycles, goals0, goals1, match.Contacts.ByKind.ToArray(),
            stats.SubSteps, stats.MostSubSteps, stats.Events, stats.LargestLeftoverOverlap, stats.LargestLeftoverCycle,
            match.Caller().TotalFaults, referee?.Item.Slug, (int[]?)referee?.Scores.Clone(), outcome?.Winner ?? -1, outcome?.Rule,
            FaultsOf(match));
    }

    // One entry per strategy that faulted, in slot (team) order; null when none did.
    private static TeamFaults[]? FaultsOf(Match match)
    {
        List<TeamFaults>? faults = null;
        foreach (var slot in match.Caller().Slots)
        {
            if (slot.Faults > 0)
            {
                (faults ??= []).Add(new TeamFaults(slot.Team, slot.Label, slot.Exceptions, slot.Timeouts, slot.BadAnswers, slot.FirstFault ?? string.Empty, slot.Crashes));
            }
        }

        return faults?.ToArray();
    }

    /// <summary>All contacts.</summary>
    public long TotalContacts
    {
        get
        {
            long sum = 0;
            foreach (long c in Contacts)
            {
                sum += c;
            }

            return sum;
        }
    }

    /// <summary>Field-by-field equality (the contact counts by value).</summary>
    public bool SameAs(MatchResult other) =>
        this with { Contacts = Array.Empty<long>(), Scores = null } == other with { Contacts = Array.Empty<long>(), Scores = null }
        && Contacts.AsSpan().SequenceEqual(other.Contacts)
        && (Scores is null ? other.Scores is null : other.Scores is not null && Scores.AsSpan().SequenceEqual(other.Scores));
}
