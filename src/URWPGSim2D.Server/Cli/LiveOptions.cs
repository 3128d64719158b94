namespace URWPGSim2D.Server.Cli;

/// <summary>The values of the live page's options, as <c>run --live</c> and <c>tournament --live</c> check them.</summary>
internal static class LiveOptions
{
    /// <summary><c>--host H</c>: an address or host name.</summary>
    /// <param name="value">The value given.</param>
    /// <param name="error">Makes the command's usage error.</param>
    public static string Host(string value, Func<string, CliUsageException> error) =>
        value.Length > 0 && !value.Contains('/', StringComparison.Ordinal) ? value : throw error($"--host must be an address or host name, got {Engine.Messages.MessageText.Quote(value)}");

    /// <summary><c>--speed X</c>: times real time, 0.01 … 1000.</summary>
    /// <param name="value">The value given.</param>
    /// <param name="error">Makes the command's usage error.</param>
    public static double Speed(string value, Func<string, CliUsageException> error) =>
        double.TryParse(value, NumberStyles.AllowDecimalPoint, CultureInfo.InvariantCulture, out double x) && x >= 0.01 && x <= 1000
            ? x : throw error($"--speed must be a number 0.01..1000 (times real time), got {Engine.Messages.MessageText.Quote(value)}");
}
