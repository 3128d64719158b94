namespace URWPGSim2D.Server.Viewer.Tests;

/// <summary>
/// A 6,000-cycle match with 4 fish and 9 balls (the size case: the default scene, with
/// two balls shot into the goals at the start so that goals happen early whatever the
/// strategies do), played once by <c>run --trace --html</c> in-process, and its page rebuilt from
/// the trace by <c>view</c>. The trace is read back as the independent truth of every check.
/// </summary>
public sealed class RecordedMatch : IDisposable
{
    /// <summary>The scenario: the default scene, ball 0 thrown into the right goal and ball 8 into the left one.</summary>
    public const string Scenario = """
        {
          "field": { "length": 3000, "width": 2000, "goalBlocks": true },
          "cycles": 6000, "seed": 7, "noise": true,
          "fish": [
            { "team": 0, "position": [-1000, -400], "heading": 0.0, "strategy": "chase-ball" },
            { "team": 0, "position": [-1000, 400], "heading": 0.0, "strategy": "chase-ball" },
            { "team": 1, "position": [1000, -400], "heading": 3.14159265, "strategy": "chase-ball" },
            { "team": 1, "position": [1000, 400], "heading": 3.14159265, "strategy": "chase-ball" }
          ],
          "balls": [
            { "position": [1150, 0], "velocity": [1500, 0] }, { "position": [0, -250] }, { "position": [250, -250] },
            { "position": [-250, 0] }, { "position": [0, 0] }, { "position": [250, 0] },
            { "position": [-250, 250] }, { "position": [0, 250] }, { "position": [-1150, 60], "velocity": [-1500, 0] }
          ],
          "obstacles": [
            { "type": "rectangle", "center": [-600, -650], "length": 100, "width": 100, "heading": 0.0 },
            { "type": "rectangle", "center": [600, 650], "length": 100, "width": 100, "heading": 0.7 },
            { "type": "round", "center": [-600, 650], "radius": 58 },
            { "type": "round", "center": [600, -650], "radius": 58 }
          ]
        }
        """;

    public RecordedMatch()
    {
        Folder = Path.Combine(Path.GetTempPath(), "urwpg-viewer-" + Guid.NewGuid().ToString("N"));
        Directory.CreateDirectory(Folder);
        string scenario = Path.Combine(Folder, "match.json");
        File.WriteAllText(scenario, Scenario);
        TracePath = Path.Combine(Folder, "match.jsonl");
        HtmlPath = Path.Combine(Folder, "match.html");
        ViewHtmlPath = Path.Combine(Folder, "view.html");
        var run = Cli("run", "--scenario", scenario, "--trace", TracePath, "--html", HtmlPath);
        Assert.True(run.Code == 0, $"run failed ({run.Code}): {run.Stderr}");
        var view = Cli("view", TracePath, "--html", ViewHtmlPath);
        Assert.True(view.Code == 0, $"view failed ({view.Code}): {view.Stderr}");
        ViewStdout = view.Stdout;
        Lines = File.ReadLines(TracePath).Select(l => JsonDocument.Parse(l).RootElement.Clone()).ToArray();
    }

    /// <summary>The temporary folder of the files.</summary>
    public string Folder { get; }

    /// <summary>The trace.</summary>
    public string TracePath { get; }

    /// <summary>The page of <c>run --html</c>.</summary>
    public string HtmlPath { get; }

    /// <summary>The page of <c>view</c>.</summary>
    public string ViewHtmlPath { get; }

    /// <summary>What <c>view</c> printed.</summary>
    public string ViewStdout { get; }

    /// <summary>Every trace line, parsed.</summary>
    public JsonElement[] Lines { get; }

    /// <summary>The layout of the cycle-0 line.</summary>
    public JsonElement Layout => Lines[0].GetProperty("layout");

    /// <summary>The cycles that have events, in order, with their texts.</summary>
    public IReadOnlyList<(int Cycle, string Text)> Events =>
        Lines.SelectMany(l => l.GetProperty("events").EnumerateArray().Select(e => (l.GetProperty("cycle").GetInt32(), e.GetProperty("text").GetString()!))).ToList();

    /// <summary>Runs the command line in-process.</summary>
    public static (int Code, string Stdout, string Stderr) Cli(params string[] args)
    {
        using var output = new StringWriter();
        using var error = new StringWriter();
        int code = CliApp.Run(args, new StringReader(string.Empty), output, error);
        return (code, output.ToString(), error.ToString());
    }

    /// <inheritdoc/>
    public void Dispose()
    {
        try
        {
            Directory.Delete(Folder, recursive: true);
        }
        catch (IOException)
        {
        }
    }
}
