using URWPGSim2D.Engine.Matches;
using URWPGSim2D.Server.Tests.Trace;

namespace URWPGSim2D.Server.Tests.Simulation;

/// <summary>The one match loop: where a match ends, what it writes, cancellation.</summary>
public sealed class MatchLoopTests
{
    [Fact]
    public void APlainSceneEndsAfterItsCyclesWithOneLineEach()
    {
        var sink = new TraceBytes();
        using var loop = new MatchLoop(new MatchSettings(DefaultScenario.Load(), 37).Build(), 37, sink);
        loop.Play();
        Assert.True(loop.IsOver);
        Assert.Equal(37, loop.Match.World.Cycle);
        Assert.Equal(38, sink.ToArray().Count(b => b == (byte)'\n')); // cycle 0 and every cycle
        Assert.False(loop.Step());
        Assert.Equal(37, loop.Match.World.Cycle);
    }

    [Fact]
    public void ATiedPoloMatchPlaysItsExtraTimeAndPenaltiesPastItsRegularTime()
    {
        // Seed 1 of polo-1v1 over 300 cycles ends 0:0 in regular time (the run command's output in docs/items.md shows the same kind of match).
        var item = ItemRegistry.Find("polo-1v1")!;
        using var loop = new MatchLoop(new MatchSettings(item.CreateScenario(1), 300, 1).Build(), 300);
        loop.Play();
        var referee = loop.Match.Referee!;
        Assert.True(referee.IsOver);
        Assert.True(loop.Match.World.Cycle > 300, $"ended at cycle {loop.Match.World.Cycle}");
        Assert.Contains(referee.Events, e => e.Kind == "period" && e.Cycle == 300);
        Assert.Contains(referee.Events, e => e.Kind == "penalty");
        Assert.Equal("end", referee.Events[^1].Kind);
        Assert.Equal(loop.Match.World.Cycle, referee.Events[^1].Cycle);
    }

    [Fact]
    public void ACancelledMatchStopsBetweenCyclesKeepingWhatWasPlayed()
    {
        using var cancel = new CancellationTokenSource();
        var sink = new TraceBytes();
        using var loop = new MatchLoop(new MatchSettings(DefaultScenario.Load(), 100).Build(), 100, sink);
        loop.Play(cancel.Token, cycle =>
        {
            if (cycle == 5)
            {
                cancel.Cancel();
            }
        });
        Assert.Equal(5, loop.Match.World.Cycle);
        string[] lines = Encoding.UTF8.GetString(sink.ToArray()).Split('\n', StringSplitOptions.RemoveEmptyEntries);
        Assert.Equal(6, lines.Length);
        Assert.StartsWith("{\"cycle\":5,", lines[^1], StringComparison.Ordinal);
    }

    [Fact]
    public void StartWritesCycleZeroOnce()
    {
        var sink = new TraceBytes();
        using var loop = new MatchLoop(new MatchSettings(DefaultScenario.Load(), 3).Build(), 3, sink, null);
        loop.Start();
        loop.Start();
        Assert.True(loop.Step());
        string[] lines = Encoding.UTF8.GetString(sink.ToArray()).Split('\n', StringSplitOptions.RemoveEmptyEntries);
        Assert.Equal(2, lines.Length);
        Assert.StartsWith("{\"cycle\":0,", lines[0], StringComparison.Ordinal);
        Assert.StartsWith("{\"cycle\":1,", lines[1], StringComparison.Ordinal);
    }

    [Fact]
    public void NegativeCyclesAreRefused()
    {
        var match = new MatchSettings(DefaultScenario.Load(), 3).Build();
        var e = Assert.Throws<ArgumentOutOfRangeException>(() => new MatchLoop(match, -1));
        Assert.Equal("cycles", e.ParamName);
        match.Teams.Stop();
    }
}
