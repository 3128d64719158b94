namespace URWPGSim2D.Hosting;

/// <summary>
/// How a team is named in summaries, traces, result files and pages: by its strategy's own name
/// (the SDK's <c>TeamName</c>, the original's <c>GetTeamName()</c>, a client's hello), with the
/// strategy's spec beside it: <c>Team First [mystrat]</c>. A strategy's name is hostile text: it
/// is cut to one short line.
/// </summary>
public static class TeamName
{
    /// <summary>The longest name shown, in characters; a longer one is cut and ends with "...".</summary>
    public const int MaximumLength = 64;

    /// <summary>
    /// The short form of a <c>--strategy</c> SPEC: a built-in name or remote:PORT as it is, a path's
    /// last part (a trailing slash, <c>.</c> and <c>..</c> included: the folder's own name).
    /// </summary>
    public static string OfSpec(string spec)
    {
        if (spec.Length == 0)
        {
            return spec;
        }

        string trimmed = Path.TrimEndingDirectorySeparator(spec);
        string last = Path.GetFileName(trimmed);
        if (last is "" or "." or "..")
        {
            try
            {
                last = Path.GetFileName(Path.TrimEndingDirectorySeparator(Path.GetFullPath(spec)));
            }
            catch (Exception e) when (e is ArgumentException or NotSupportedException or PathTooLongException)
            {
                return spec;
            }
        }

        return last.Length == 0 ? spec : last;
    }

    /// <summary>A strategy's own name made fit to show: one line, at most <see cref="MaximumLength"/> characters; null when it has none.</summary>
    public static string? Clean(string? raw)
    {
        if (string.IsNullOrWhiteSpace(raw))
        {
            return null;
        }

        var text = new StringBuilder(Math.Min(raw.Length, MaximumLength + 3));
        foreach (char c in raw)
        {
            text.Append(char.IsControl(c) || c is '\u2028' or '\u2029' ? ' ' : c);
            if (text.Length > MaximumLength)
            {
                text.Length = MaximumLength;
                text.Append("...");
                break;
            }
        }

        string name = text.ToString().Trim();
        return name.Length == 0 ? null : name;
    }

    /// <summary>The label of a team: the name with the spec beside it, or the spec alone when the name is unknown or the same.</summary>
    public static string Label(string? name, string spec) =>
        name is null || name == spec ? spec : $"{name} [{spec}]";
}
