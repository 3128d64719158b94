using Microsoft.CodeAnalysis;
using Microsoft.CodeAnalysis.CSharp;

namespace URWPGSim2D.Server.Tests.Hosting;

/// <summary>Compiles C# source into a strategy DLL in a fresh temporary folder, as a team would ship it.</summary>
internal static class StrategyAssemblyBuilder
{
    /// <summary>Builds <paramref name="name"/>.dll from <paramref name="source"/> and returns its path.</summary>
    public static string Build(string name, string source)
    {
        var references = new List<MetadataReference>();
        string trusted = (string)AppContext.GetData("TRUSTED_PLATFORM_ASSEMBLIES")!;
        foreach (string path in trusted.Split(Path.PathSeparator))
        {
            references.Add(MetadataReference.CreateFromFile(path));
        }

        references.Add(MetadataReference.CreateFromFile(typeof(IStrategy).Assembly.Location));
        var compilation = CSharpCompilation.Create(
            name,
            [CSharpSyntaxTree.ParseText(source)],
            references,
            new CSharpCompilationOptions(OutputKind.DynamicallyLinkedLibrary));
        string folder = Path.Combine(Path.GetTempPath(), "urwpg-strategy-" + Guid.NewGuid().ToString("N"));
        Directory.CreateDirectory(folder);
        string dll = Path.Combine(folder, name + ".dll");
        var result = compilation.Emit(dll);
        if (!result.Success)
        {
            throw new InvalidOperationException(string.Join("\n", result.Diagnostics));
        }

        return dll;
    }
}
