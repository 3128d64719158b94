using System.IO;

namespace URWPGSim2D.Testing;

/// <summary>
/// The source of a strategy written against the SDK (one class implementing <c>IStrategy</c>), for a
/// test to write where a command loads strategies from.
/// </summary>
public static class SdkStrategy
{
    /// <summary>The namespaces a strategy's source uses unless it names its own: System and the SDK's.</summary>
    public const string Usings = "using System; using URWPGSim2D.Strategies;";

    /// <summary>
    /// Writes <paramref name="folder"/>/<paramref name="type"/>.cs, the <see cref="Source"/> of the
    /// strategy, and returns the file's path.
    /// </summary>
    public static string Write(string folder, string type, string team, string decide, string members = "", string usings = Usings)
    {
        string path = Path.Combine(folder, type + ".cs");
        File.WriteAllText(path, Source(type, team, decide, members, usings));
        return path;
    }

    /// <summary>
    /// A strategy of class <paramref name="type"/> whose team is named <paramref name="team"/> (a C#
    /// string literal's text), with the <paramref name="members"/> and whose <c>Decide(s, fish, d)</c>
    /// runs the statements <paramref name="decide"/>, after the <paramref name="usings"/>.
    /// </summary>
    public static string Source(string type, string team, string decide, string members = "", string usings = Usings) => usings + "\n" + $$"""
        public sealed class {{type}} : IStrategy
        {
            {{members}}
            public string TeamName => "{{team}}";
            public void Decide(MatchSnapshot s, ReadOnlySpan<int> fish, Span<Decision> d)
            {
        {{decide}}
            }
        }
        """;
}
