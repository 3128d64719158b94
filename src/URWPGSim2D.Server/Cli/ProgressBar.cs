using System.Globalization;
using System.IO;

namespace URWPGSim2D.Server.Cli;

/// <summary>A one-line progress bar redrawn in place with a carriage return (terminals only).</summary>
internal sealed class ProgressBar(TextWriter output, int total)
{
    private const int Width = 40;
    private int _shownPercent = -1;

    /// <summary>Redraws when the percentage changes.</summary>
    public void Update(int done)
    {
        int percent = total <= 0 ? 100 : (int)(100L * done / total);
        if (percent == _shownPercent)
        {
            return;
        }

        _shownPercent = percent;
        int filled = percent * Width / 100;
        output.Write(string.Create(CultureInfo.InvariantCulture, $"\r[{new string('#', filled)}{new string('-', Width - filled)}] {percent,3}% cycle {done}/{total}"));
        output.Flush();
    }

    /// <summary>Erases the bar.</summary>
    public void Clear()
    {
        output.Write("\r" + new string(' ', Width + 40) + "\r");
        output.Flush();
    }
}
