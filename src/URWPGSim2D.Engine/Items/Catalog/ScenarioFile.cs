using System.Text.Json;

namespace URWPGSim2D.Engine.Items.Catalog;

/// <summary>
/// Reads a scenario file (docs/scenario.md): one that names a competition item (<c>"item"</c>) is
/// that item's layout and rules (<see cref="ItemScenarioParser"/>), any other a plain scene
/// (<see cref="ScenarioParser"/>). Any problem throws <see cref="ScenarioException"/> naming the JSON path.
/// </summary>
public static class ScenarioFile
{
    /// <summary>Parses and validates scenario JSON text.</summary>
    /// <param name="json">The file's text.</param>
    public static ScenarioDefinition Parse(string json) => ScenarioParser.ParseDocument(json, root =>
        root.TryGetProperty("item", out var item) ? ItemScenarioParser.Parse(root, item) : ScenarioParser.ReadPlain(root));
}
