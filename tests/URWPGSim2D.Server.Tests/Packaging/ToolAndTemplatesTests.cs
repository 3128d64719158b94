using System.Xml.Linq;

namespace URWPGSim2D.Server.Tests.Packaging;

/// <summary>
/// The tool and template packages as users meet them: the command name, each template's short
/// name and parameters, and the docs that tell users about them. (.ci/pack and .ci/release pack,
/// install and play them.)
/// </summary>
public sealed class ToolAndTemplatesTests
{
    [Fact]
    public void TheServerPacksAsTheToolUrwpgsim2d()
    {
        var project = XDocument.Load(Repository.PathOf("src/URWPGSim2D.Server/URWPGSim2D.Server.csproj"));
        string? Property(string name) => project.Descendants(name).SingleOrDefault()?.Value;
        Assert.Equal("true", Property("PackAsTool"));
        Assert.Equal("urwpgsim2d", Property("ToolCommandName"));
        Assert.Equal("URWPGSim2D.Server", Property("PackageId"));
        Assert.Contains(project.Descendants("Import"), i => i.Attribute("Project")!.Value.EndsWith("PackageMetadata.props", System.StringComparison.Ordinal));
        Assert.True(File.Exists(Repository.PathOf("src/URWPGSim2D.Server/README.md")));
    }

    [Theory]
    [InlineData("StrategySdk", "urwpgsim2d-strategy", "URWPGSim2D.Strategies")]
    [InlineData("Strategy", "urwpgsim2d-strategy-original", "URWPGSim2D.Compat")]
    public void EachTemplateMakesAProjectOnThePackagesOfItsOwnVersion(string folder, string shortName, string package)
    {
        using var json = JsonDocument.Parse(File.ReadAllText(Repository.PathOf($"templates/{folder}/.template.config/template.json")));
        var root = json.RootElement;
        Assert.Equal(shortName, root.GetProperty("shortName").GetString());
        Assert.Equal("MyTeam", root.GetProperty("sourceName").GetString());
        var version = root.GetProperty("symbols").GetProperty("UrwpgVersion");
        Assert.Equal("URWPGSIM2D_PACKAGE_VERSION", version.GetProperty("defaultValue").GetString()); // stamped at pack time
        string token = version.GetProperty("replaces").GetString()!;
        var team = root.GetProperty("symbols").GetProperty("TeamName");
        string teamName = team.GetProperty("replaces").GetString()!;

        // Outside the repository the project references the package at the stamped version.
        var project = XDocument.Load(Repository.PathOf($"templates/{folder}/Strategy.csproj"));
        var reference = project.Descendants("PackageReference").Single();
        Assert.Equal(package, reference.Attribute("Include")!.Value);
        Assert.Equal(token, reference.Attribute("Version")!.Value);
        Assert.Equal("'$(UrwpgSim2DRepository)' != 'true'", reference.Parent!.Attribute("Condition")!.Value);
        Assert.Contains("MyTeam", project.Descendants("AssemblyName").Single().Value, System.StringComparison.Ordinal);

        // The strategy's own name is the TeamName parameter.
        Assert.Contains($"\"{teamName}\"", File.ReadAllText(Repository.PathOf($"templates/{folder}/Strategy.cs")), System.StringComparison.Ordinal);

        // The template package carries the folder, and the docs name the short name.
        string pack = File.ReadAllText(Repository.PathOf("templates/URWPGSim2D.Templates.csproj"));
        Assert.Contains($"{folder}/.template.config/template.json", pack, System.StringComparison.Ordinal);
        Assert.Contains($"dotnet new {shortName}", File.ReadAllText(Repository.PathOf("docs/packaging.md")), System.StringComparison.Ordinal);
    }

    [Fact]
    public void TheReadmeKeepsItsSetUpCommandsAndInstallsTheTool()
    {
        string readme = File.ReadAllText(Repository.PathOf("README.md"));
        Assert.Contains("dotnet run -c Release --project src/URWPGSim2D.Server\n", readme, System.StringComparison.Ordinal);
        Assert.Contains("bash .ci/test\n", readme, System.StringComparison.Ordinal);
        Assert.Contains("dotnet tool install -g URWPGSim2D.Server", readme, System.StringComparison.Ordinal);
        Assert.Contains("dotnet new install URWPGSim2D.Templates", readme, System.StringComparison.Ordinal);
    }

    [Fact]
    public void EveryPackageTakesItsVersionFromOnePlace()
    {
        // version.props names the release; the libraries and the tool (PackageMetadata.props) and the
        // templates import it, and no project writes a version of its own.
        var release = XDocument.Load(Repository.PathOf("version.props")).Descendants("UrwpgReleaseVersion").Single().Value;
        Assert.Matches(@"^\d+\.\d+\.\d+$", release);
        Assert.NotEqual("1.0.0", release); // every earlier pack was 1.0.0: a tool installed from one must see this as newer
        foreach (string file in new[] { "src/PackageMetadata.props", "templates/URWPGSim2D.Templates.csproj" })
        {
            var project = XDocument.Load(Repository.PathOf(file));
            Assert.Contains(project.Descendants("Import"), i => i.Attribute("Project")!.Value.EndsWith("version.props", System.StringComparison.Ordinal));
            Assert.Equal("$(UrwpgReleaseVersion)", project.Descendants("Version").Single().Value);
        }

        var versioned = Directory.EnumerateFiles(Repository.PathOf("src"), "*.*proj*", SearchOption.AllDirectories)
            .Concat(Directory.EnumerateFiles(Repository.PathOf("src"), "*.props", SearchOption.AllDirectories))
            .Where(f => !f.Contains($"{Path.DirectorySeparatorChar}obj{Path.DirectorySeparatorChar}", System.StringComparison.Ordinal))
            .Where(f => XDocument.Load(f).Descendants("Version").Any(v => v.Value != "$(UrwpgReleaseVersion)"));
        Assert.Empty(versioned);
        Assert.Contains($"--version {release}", File.ReadAllText(Repository.PathOf("docs/packaging.md")), System.StringComparison.Ordinal);
    }

    [Fact]
    public void TheReadmesFeedIsIgnoredAndTheToolsFolderIsOnThePath()
    {
        // The README packs into feed/ inside the clone: git must not offer the packages for a commit.
        Assert.Contains("/feed/", File.ReadAllLines(Repository.PathOf(".gitignore")));
        string readme = File.ReadAllText(Repository.PathOf("README.md"));
        Assert.Contains("export PATH=\"$PATH:$HOME/.dotnet/tools\"", readme, System.StringComparison.Ordinal);
        Assert.Contains("dotnet tool update -g URWPGSim2D.Server", readme, System.StringComparison.Ordinal);
    }
}
