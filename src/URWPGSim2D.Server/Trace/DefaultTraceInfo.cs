using System;
using System.Collections.Generic;
using System.Globalization;
using URWPGSim2D.Server.Items;
using URWPGSim2D.Server.Simulation;

namespace URWPGSim2D.Server.Trace;

/// <summary>
/// The trace's item information for a match without an item (a plain scenario or the old default
/// scene): slug "default", no zones, the world's goals as the score and this cycle's goals as
/// <c>goal</c> events (value 1, the ball is put back at its start).
/// </summary>
internal sealed class DefaultTraceInfo(Match match) : ITraceItemInfo
{
    private readonly List<ItemEvent> _events = new(4);
    private int _seen;

    /// <inheritdoc/>
    public string ItemSlug => "default";

    /// <inheritdoc/>
    public IReadOnlyList<ItemZone> Zones => Array.Empty<ItemZone>();

    /// <inheritdoc/>
    public ReadOnlySpan<int> TeamScores => match.World.Goals;

    /// <inheritdoc/>
    public ReadOnlySpan<ItemEvent> CycleEvents
    {
        get
        {
            if (_seen != match.Goals.Count)
            {
                _events.Clear();
                for (int i = _seen; i < match.Goals.Count; i++)
                {
                    GoalEvent g = match.Goals[i];
                    _events.Add(new ItemEvent(g.Cycle, "goal", g.Team, -1, g.Ball, 1, string.Create(CultureInfo.InvariantCulture, $"team {g.Team} scores ball {g.Ball}")));
                }

                _seen = match.Goals.Count;
            }
            else if (_events.Count > 0 && _events[0].Cycle != match.World.Cycle)
            {
                _events.Clear();
            }

            return System.Runtime.InteropServices.CollectionsMarshal.AsSpan(_events);
        }
    }

    /// <inheritdoc/>
    public double BallValue(int ball) => double.NaN;
}
