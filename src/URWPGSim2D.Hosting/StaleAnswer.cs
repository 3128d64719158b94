using System.Text.Json;

namespace URWPGSim2D.Hosting;

/// <summary>
/// Recognises a host's <c>decisions</c> line for a cycle before the current one. Such a line is left
/// in the pipe when a bad line (garbage, another cycle's number) was read in its place; its cycle
/// has been charged already, so the server skips it and the host is back in step.
/// </summary>
internal static class StaleAnswer
{
    /// <summary>Whether <paramref name="line"/> is a well-formed object of type <c>decisions</c> whose <c>cycle</c> is below <paramref name="cycle"/>.</summary>
    public static bool Is(ReadOnlySpan<byte> line, int cycle)
    {
        try
        {
            var r = new Utf8JsonReader(line);
            if (!r.Read() || r.TokenType != JsonTokenType.StartObject)
            {
                return false;
            }

            bool decisions = false;
            int? answered = null;
            while (r.Read() && r.TokenType == JsonTokenType.PropertyName)
            {
                bool isType = r.ValueTextEquals("type"u8), isCycle = r.ValueTextEquals("cycle"u8);
                if (!r.Read())
                {
                    return false;
                }

                if (isType && r.TokenType == JsonTokenType.String)
                {
                    decisions = r.ValueTextEquals("decisions"u8);
                }
                else if (isCycle && r.TokenType == JsonTokenType.Number && r.TryGetInt32(out int c))
                {
                    answered = c;
                }
                else
                {
                    r.Skip();
                }
            }

            return decisions && answered < cycle;
        }
        catch (JsonException)
        {
            return false;
        }
    }
}
