namespace URWPGSim2D.Engine.Scenario;

/// <summary>
/// The embedded default match, the paper's scene: the 3000 × 2000 pool with goal blocks, two teams
/// of two fish (team 0 on the left attacking +X, team 1 on the right attacking −X), nine balls in a
/// 3 × 3 grid around the centre, two rectangular and two round obstacles, 3,000 cycles (five
/// minutes), every fish on chase-ball, noise on, seed 1.
/// </summary>
public static class DefaultScenario
{
    /// <summary>The scenario file text.</summary>
    public const string Json = """
        {
          "field": { "length": 3000, "width": 2000, "goalBlocks": true },
          "cycles": 3000,
          "seed": 1,
          "noise": true,
          "fish": [
            { "team": 0, "position": [-1000, -400], "heading": 0.0, "strategy": "chase-ball" },
            { "team": 0, "position": [-1000, 400], "heading": 0.0, "strategy": "chase-ball" },
            { "team": 1, "position": [1000, -400], "heading": 3.14159265, "strategy": "chase-ball" },
            { "team": 1, "position": [1000, 400], "heading": 3.14159265, "strategy": "chase-ball" }
          ],
          "balls": [
            { "position": [-250, -250] }, { "position": [0, -250] }, { "position": [250, -250] },
            { "position": [-250, 0] }, { "position": [0, 0] }, { "position": [250, 0] },
            { "position": [-250, 250] }, { "position": [0, 250] }, { "position": [250, 250] }
          ],
          "obstacles": [
            { "type": "rectangle", "center": [-600, -650], "length": 100, "width": 100, "heading": 0.0 },
            { "type": "rectangle", "center": [600, 650], "length": 100, "width": 100, "heading": 0.0 },
            { "type": "round", "center": [-600, 650], "radius": 58 },
            { "type": "round", "center": [600, -650], "radius": 58 }
          ]
        }
        """;

    /// <summary>The parsed default match.</summary>
    public static ScenarioDefinition Load() => ScenarioParser.Parse(Json);
}
