using System;
using System.Linq;
using URWPGSim2D.Engine.BuiltInStrategies;
using URWPGSim2D.Engine.Items.Catalog;
using URWPGSim2D.Engine.Matches;

// A whole match of an item in twenty lines, with the engine package alone: the same match as
// `urwpgsim2d run --item polo-1v1 --seed 1 --strategy 0=chase-ball`.
// <snippet>
var item = ItemRegistry.Find("polo-1v1") ?? throw new InvalidOperationException("unknown item");
var scenario = item.CreateScenario(seed: 1);

// Team 0 plays chase-ball; team 1 (null) plays what the scenario names: the item's demo.
var match = MatchSetup.Create(scenario, [new ChaseBallStrategy(), null]);
var loop = new MatchLoop(match, scenario.Cycles);
loop.Start();
while (loop.Step())
{
    var ball = match.Snapshot.Balls[0]; // what the strategies saw this cycle
    if (match.World.Cycle % 300 == 0)
    {
        Console.WriteLine($"cycle {match.World.Cycle}: ball at ({ball.Position.X:F0}, {ball.Position.Y:F0})");
    }
}

loop.Dispose(); // ends the strategies

var scores = match.Rules.Scores;
Console.WriteLine($"{match.TeamLabel(0)} {scores[0]} : {scores[1]} {match.TeamLabel(1)} after {match.World.Cycle} cycles, {match.Rules.Events.Count} events");
// </snippet>

// The sample checks itself: the match was played to its end, and every team has a score.
if (match.World.Cycle < scenario.Cycles || !loop.IsOver || scores.Length != 2 || scores.Any(s => s < 0))
{
    Console.Error.WriteLine($"EmbeddedMatch: the match stopped early or has no score (cycle {match.World.Cycle})");
    return 1;
}

return 0;
