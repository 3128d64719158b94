namespace URWPGSim2D.Server.Cli;

/// <summary>
/// A one-line progress bar redrawn in place with a carriage return (terminals only). With a
/// clock, it also shows the time left, estimated from the rate so far.
/// </summary>
/// <param name="output">The terminal.</param>
/// <param name="total">The count at 100 %.</param>
/// <param name="unit">What is counted, e.g. <c>cycle</c> or <c>match</c>.</param>
/// <param name="clock">A clock started when the work started, or null for no estimate.</param>
internal sealed class ProgressBar(TextWriter output, int total, string unit = "cycle", System.Diagnostics.Stopwatch? clock = null)
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
        output.Write(string.Create(CultureInfo.InvariantCulture, $"\r[{new string('#', filled)}{new string('-', Width - filled)}] {percent,3}% {unit} {done}/{total}{Left(done)}"));
        output.Flush();
    }

    /// <summary>The estimated time left, e.g. <c>, about 1 min 20 s left</c>, or nothing before the first unit is done.</summary>
    private string Left(int done)
    {
        if (clock is null || done <= 0 || done >= total)
        {
            return string.Empty;
        }

        double seconds = clock.Elapsed.TotalSeconds / done * (total - done);
        return seconds >= 60
            ? string.Create(CultureInfo.InvariantCulture, $", about {(int)(seconds / 60)} min {(int)(seconds % 60)} s left   ")
            : string.Create(CultureInfo.InvariantCulture, $", about {(int)seconds + 1} s left   ");
    }

    /// <summary>Erases the bar.</summary>
    public void Clear()
    {
        output.Write("\r" + new string(' ', Width + 80) + "\r");
        output.Flush();
    }
}
