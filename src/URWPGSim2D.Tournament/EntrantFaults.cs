using System.Text.RegularExpressions;

namespace URWPGSim2D.Tournament;

/// <summary>
/// The runtime faults of one entrant's strategy over the matches it played: calls that threw, that
/// missed their deadline, that answered badly, and hosts that ended before their match did; and its
/// first fault (the match with the lowest index that had one).
/// </summary>
/// <param name="Exceptions">Calls that threw.</param>
/// <param name="Timeouts">Calls that missed their deadline.</param>
/// <param name="BadAnswers">Calls that returned null or too few decisions.</param>
/// <param name="HostEnds">Matches whose strategy host ended before the match did.</param>
/// <param name="Matches">Matches with at least one fault.</param>
/// <param name="FirstMatch">The index of the first match with a fault.</param>
/// <param name="FirstCycle">The cycle of that match's first fault, or null when not known.</param>
/// <param name="FirstText">That fault's message.</param>
public sealed partial record EntrantFaults(int Exceptions, int Timeouts, int BadAnswers, int HostEnds, int Matches, int FirstMatch, int? FirstCycle, string FirstText)
{
    /// <summary>All faults.</summary>
    public int Total => Exceptions + Timeouts + BadAnswers + HostEnds;

    /// <summary>
    /// These faults with one more entry of the results added: <paramref name="faults"/> of match
    /// <paramref name="match"/> (matches in index order); <paramref name="newMatch"/> when the entrant had
    /// no fault in that match before.
    /// </summary>
    public static EntrantFaults Add(EntrantFaults? sum, int match, TeamFaults faults, bool newMatch)
    {
        if (sum is null)
        {
            var (cycle, text) = Split(faults.First);
            return new EntrantFaults(faults.Exceptions, faults.Timeouts, faults.BadAnswers, faults.Crashes, 1, match, cycle, text);
        }

        return sum with
        {
            Exceptions = sum.Exceptions + faults.Exceptions,
            Timeouts = sum.Timeouts + faults.Timeouts,
            BadAnswers = sum.BadAnswers + faults.BadAnswers,
            HostEnds = sum.HostEnds + faults.Crashes,
            Matches = sum.Matches + (newMatch ? 1 : 0),
        };
    }

    /// <summary>The counts in words, e.g. <c>60 exceptions, 1 timeout in 2 matches</c> (kinds that did not happen left out).</summary>
    public string Counts()
    {
        var parts = new System.Collections.Generic.List<string>(4);
        Part(Exceptions, "exception", "exceptions");
        Part(Timeouts, "timeout", "timeouts");
        Part(BadAnswers, "bad answer", "bad answers");
        Part(HostEnds, "host end", "host ends");
        return string.Join(", ", parts) + (Matches == 1 ? " in 1 match" : string.Create(CultureInfo.InvariantCulture, $" in {Matches} matches"));

        void Part(int n, string one, string many)
        {
            if (n > 0)
            {
                parts.Add(string.Create(CultureInfo.InvariantCulture, $"{n} {(n == 1 ? one : many)}"));
            }
        }
    }

    /// <summary>Where the first fault is, e.g. <c>match 3, cycle 120</c>.</summary>
    public string Where() => FirstCycle is { } c
        ? string.Create(CultureInfo.InvariantCulture, $"match {FirstMatch}, cycle {c}")
        : string.Create(CultureInfo.InvariantCulture, $"match {FirstMatch}");

    /// <summary>The link to the first fault in its match's replay page, relative to the tournament's folder: <c>replays/match-J.html#cycle=N</c>.</summary>
    public string ReplayLink() =>
        TournamentOutputs.Replays + "/" + string.Create(CultureInfo.InvariantCulture, $"match-{FirstMatch}.html") + (FirstCycle is { } c ? string.Create(CultureInfo.InvariantCulture, $"#cycle={c}") : string.Empty);

    // A strategy's first fault as the results keep it: "cycle N: message".
    private static (int? Cycle, string Text) Split(string first)
    {
        var m = FirstFault().Match(first);
        return m.Success && int.TryParse(m.Groups[1].ValueSpan, NumberStyles.None, CultureInfo.InvariantCulture, out int cycle)
            ? (cycle, m.Groups[2].Value)
            : (null, first);
    }

    [GeneratedRegex(@"^cycle (\d+): (.*)$", RegexOptions.Singleline | RegexOptions.CultureInvariant)]
    private static partial Regex FirstFault();
}
