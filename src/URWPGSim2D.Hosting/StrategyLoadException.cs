using System.Linq;

namespace URWPGSim2D.Hosting;

/// <summary>
/// A user strategy could not be loaded. The message is one line for the command line; compile
/// errors add one <see cref="Details"/> line each (<c>file(line,col): error CSnnnn: message</c>).
/// Both hold text a strategy controls (its files' names, its sources, its messages): control and
/// escape characters in them are escaped, so each is one harmless line on a terminal.
/// </summary>
public class StrategyLoadException : Exception
{
    /// <summary>Creates the exception.</summary>
    /// <param name="message">What went wrong, one line.</param>
    /// <param name="details">Further lines (compile errors), or none.</param>
    public StrategyLoadException(string message, IReadOnlyList<string>? details = null)
        : base(Engine.Messages.MessageText.Escape(message))
    {
        Details = details is null ? [] : details.Select(Engine.Messages.MessageText.Escape).ToArray();
    }

    /// <summary>Lines printed after the message, one per compile error.</summary>
    public IReadOnlyList<string> Details { get; }

    /// <summary>The message and then the details, the lines the command prints.</summary>
    public IEnumerable<string> Lines
    {
        get
        {
            yield return Message;
            foreach (string line in Details)
            {
                yield return line;
            }
        }
    }
}
