using URWPGSim2D.Viewer;

namespace URWPGSim2D.Server.Tests.Viewer;

/// <summary>The live view plays the match the match loop plays: to the item's end, extra periods included.</summary>
public sealed class LiveMatchTests
{
    [Fact]
    public async Task ATiedPoloMatchShowsItsExtraTimeAndPenaltiesLive()
    {
        var item = ItemRegistry.Find("polo-1v1")!;
        var settings = new MatchSettings(item.CreateScenario(1), 300, 1);
        var feed = new LiveFeed();
        var player = new LiveMatch(() => (settings.Build(), settings.Cycles), speed: 1e9, paused: false, feed);
        using var stop = new CancellationTokenSource();
        var playing = Task.Run(() => player.Run(stop.Token));

        // Read the feed until a status says the match is over (the playing thread publishes it after the last cycle).
        var messages = new List<byte[]>();
        int next = 0, generation = 0;
        JsonElement? last = null;
        using var give = new CancellationTokenSource(TimeSpan.FromMinutes(2)); // a hang fails instead of blocking the run
        while (last is not { } s || !s.GetProperty("over").GetBoolean())
        {
            var changed = feed.Changed;
            int before = messages.Count;
            generation = feed.Read(generation, ref next, messages, 4096); // as a viewer's connection reads
            last = messages.Skip(before).Select(Status).LastOrDefault(x => x is not null) ?? last;
            if (messages.Count == before)
            {
                await changed.WaitAsync(give.Token);
            }
        }

        stop.Cancel();
        await playing;
        player.Match.Teams.Stop();

        int cycle = last.Value.GetProperty("cycle").GetInt32();
        Assert.True(cycle > 300, $"the live match ended at cycle {cycle}");
        Assert.Equal(player.Match.World.Cycle, cycle);
        string trace = string.Concat(messages.Select(m => Encoding.UTF8.GetString(m)));
        Assert.Contains("\"kind\":\"penalty\"", trace, StringComparison.Ordinal);
        Assert.Contains("\"kind\":\"end\"", trace, StringComparison.Ordinal);
    }

    // The JSON of a status message, or null for a cycle line.
    private static JsonElement? Status(byte[] message)
    {
        string text = Encoding.UTF8.GetString(message);
        const string Prefix = "event: status\ndata: ";
        return text.StartsWith(Prefix, StringComparison.Ordinal) ? JsonDocument.Parse(text[Prefix.Length..].Trim()).RootElement.Clone() : null;
    }
}
