using System.IO;
using System.Linq;
using System.Text.Json;
using System.Xml.Linq;
using URWPGSim2D.Server.Tests.Docs;
using Xunit;

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
    [InlineData("StrategySdk", "urwpgsim2d-strategy", "URWPGSim2D.Strategy")]
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
}
