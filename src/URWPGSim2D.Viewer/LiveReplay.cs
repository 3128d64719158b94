namespace URWPGSim2D.Viewer;

/// <summary>
/// The replay page of what the live view has played so far (<c>GET /replay.html</c>): the cycle
/// lines of the feed's current match packed by a <see cref="ReplayRecorder"/> into the page
/// <c>run --html</c> writes, so a whole match saved from the live view is the same bytes as its
/// <c>run --html</c> page.
/// </summary>
internal static class LiveReplay
{
    private static readonly byte[] DataPrefix = "data: "u8.ToArray();

    /// <summary>The page and the cycle it ends at, or null when the feed holds no cycle line yet.</summary>
    public static (string Page, int LastCycle)? Build(LiveFeed feed)
    {
        var messages = new List<byte[]>();
        int next = 0;
        feed.Read(int.MinValue, ref next, messages, int.MaxValue); // a generation no reader has: everything of the current one
        var recorder = new ReplayRecorder();
        foreach (byte[] message in messages)
        {
            if (message.AsSpan().StartsWith(DataPrefix))
            {
                recorder.Add(message.AsSpan(DataPrefix.Length, message.Length - DataPrefix.Length - 2)); // the line, without "\n\n"
            }
        }

        return recorder.Count == 0 ? null : (ReplayPage.Replay(recorder.ToJson()), recorder.Count - 1);
    }

    /// <summary>The file name a browser saves the page as.</summary>
    public static string FileName(int lastCycle) => string.Create(CultureInfo.InvariantCulture, $"match-cycle{lastCycle}.html");
}
