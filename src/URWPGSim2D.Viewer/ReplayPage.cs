using System.IO;
using System.Reflection;

namespace URWPGSim2D.Viewer;

/// <summary>
/// The viewer page (embedded resources Viewer/Assets/viewer.html, .css, .js) with everything
/// inline: a replay page carries the packed match (<see cref="ReplayRecorder.ToJson"/>), the live
/// page only <c>{"live":true}</c> (and <c>"board":true</c> when the server has a control board) and follows the server's event stream.
/// </summary>
public static class ReplayPage
{
    private static readonly Lazy<string> Template = new(() =>
        Resource("viewer.html")
            .Replace("/*@style*/", Resource("viewer.css"), StringComparison.Ordinal)
            .Replace("/*@script*/", Resource("viewer.js"), StringComparison.Ordinal));

    /// <summary>The replay page of a match.</summary>
    /// <param name="dataJson">The packed match, as <see cref="ReplayRecorder.ToJson"/> makes it.</param>
    public static string Replay(string dataJson) => Fill(dataJson);

    /// <summary>The live page (served by the live view at <c>/</c>).</summary>
    /// <param name="board">Whether the server has a control board (<c>run --live --strategies DIR</c>).</param>
    public static string Live(bool board = false) => Fill(board ? "{\"live\":true,\"board\":true}" : "{\"live\":true}");

    private static string Fill(string dataJson)
    {
        string t = Template.Value;
        int at = t.IndexOf("/*@data*/", StringComparison.Ordinal);
        return string.Concat(t.AsSpan(0, at), dataJson, t.AsSpan(at + "/*@data*/".Length));
    }

    private static string Resource(string name)
    {
        using var stream = Assembly.GetExecutingAssembly().GetManifestResourceStream("URWPGSim2D.Viewer." + name)
            ?? throw new InvalidOperationException($"embedded resource {name} is missing from the build");
        using var reader = new StreamReader(stream);
        return reader.ReadToEnd();
    }
}
