using System.Text.Encodings.Web;
using System.Text.Json;

namespace URWPGSim2D.Server.Cli;

/// <summary>Text helpers for one-line messages.</summary>
internal static class CliText
{
    /// <summary>A user-supplied string as a JSON string literal (quoted, control characters escaped), so a message stays on one line.</summary>
    /// <param name="value">Any string.</param>
    /// <returns>E.g. <c>"triangle"</c>, or <c>"tri\nangle"</c> for a string holding a line break.</returns>
    public static string Quote(string value) =>
        $"\"{JsonEncodedText.Encode(value, JavaScriptEncoder.UnsafeRelaxedJsonEscaping)}\"";
}
