using System;
using System.Collections.Generic;
using URWPGSim2D.Server.Items;

namespace URWPGSim2D.Server.Trace;

/// <summary>
/// What the trace writes about the item being played (docs/simulation.md, "Trace"): the item slug
/// and its zones and ball values on the cycle-0 line, the per-team score and the events of the
/// cycle on every line. Implemented by every item's referee and, for a plain scenario, by
/// <see cref="DefaultTraceInfo"/> (slug "default", goals of the world, goal events).
/// </summary>
internal interface ITraceItemInfo
{
    /// <summary>The item slug ("ball-grab", …, or "default").</summary>
    string ItemSlug { get; }

    /// <summary>The item's marked regions (goal boxes, holes, parking places), possibly none.</summary>
    IReadOnlyList<ItemZone> Zones { get; }

    /// <summary>Score per team, team 0 first.</summary>
    ReadOnlySpan<int> TeamScores { get; }

    /// <summary>The events of the last cycle judged (none before the first).</summary>
    ReadOnlySpan<ItemEvent> CycleEvents { get; }

    /// <summary>The value of a ball in this item, or NaN when balls have no value.</summary>
    /// <param name="ball">Ball index.</param>
    double BallValue(int ball);
}
