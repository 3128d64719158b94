using System.Text.RegularExpressions;

namespace URWPGSim2D.Server.Tests;

/// <summary>
/// The command line's floors point one way: the commands (<c>Cli/</c>) sit on top and the folders
/// below them in the same project never name a command's type (no error type, summary or option
/// of the command line leaks down). Checked on the sources: no file of a lower folder names a type
/// declared under <c>Cli/</c> or the <c>Cli</c> namespace (comments aside). The libraries under
/// the command (hosting, viewer, tournament, engine) cannot name it at all: they do not reference it.
/// </summary>
public sealed partial class LayeringTests
{
    private static readonly string[] Lower = ["Json", "Rendering"];

    [Fact]
    public void NoLowerFolderReachesUpIntoCli()
    {
        string server = Repository.PathOf("src/URWPGSim2D.Server");
        var cliTypes = Directory.EnumerateFiles(Path.Combine(server, "Cli"), "*.cs")
            .SelectMany(f => Declared().Matches(File.ReadAllText(f)).Select(m => m.Groups[1].Value))
            .ToHashSet(StringComparer.Ordinal);
        Assert.Contains("RunCommand", cliTypes); // the scan sees the commands

        var reaches = new List<string>();
        foreach (string folder in Lower)
        {
            foreach (string file in Directory.EnumerateFiles(Path.Combine(server, folder), "*.cs", SearchOption.AllDirectories))
            {
                string code = Comment().Replace(File.ReadAllText(file), string.Empty);
                foreach (Match name in Identifier().Matches(code))
                {
                    if (cliTypes.Contains(name.Value) || name.Value == "Cli")
                    {
                        reaches.Add($"{Path.GetRelativePath(server, file)}: {name.Value}");
                    }
                }
            }
        }

        Assert.Empty(reaches);
    }

    [GeneratedRegex(@"\b(?:class|record|struct|interface|enum)\s+([A-Z]\w*)")]
    private static partial Regex Declared();

    [GeneratedRegex(@"//[^\n]*")]
    private static partial Regex Comment();

    [GeneratedRegex(@"\b[A-Z]\w*\b")]
    private static partial Regex Identifier();
}
