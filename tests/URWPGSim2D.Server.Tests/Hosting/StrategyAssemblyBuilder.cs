using Microsoft.CodeAnalysis;
using Microsoft.CodeAnalysis.CSharp;

namespace URWPGSim2D.Server.Tests.Hosting;

/// <summary>Compiles C# source into a strategy DLL in a fresh temporary folder, as a team would ship it.</summary>
internal static class StrategyAssemblyBuilder
{
    /// <summary>The strategy SDK's former assembly name, which strategies compiled before the rename reference.</summary>
    public const string FormerSdkName = "URWPGSim2D.Strategy";

    /// <summary>Builds <paramref name="name"/>.dll from <paramref name="source"/> and returns its path.</summary>
    public static string Build(string name, string source)
    {
        var references = PlatformReferences(except: null);
        references.Add(MetadataReference.CreateFromFile(typeof(IStrategy).Assembly.Location));
        return Emit(name, source, references);
    }

    /// <summary>
    /// Builds <paramref name="name"/>.dll from <paramref name="source"/> against the SDK under its former
    /// assembly name (the SDK's own image, renamed <see cref="FormerSdkName"/>), as a team compiled it
    /// before the rename: the DLL references <see cref="FormerSdkName"/>, not the SDK's name. The renamed
    /// SDK is written beside it too, as a team whose project copied it would ship it.
    /// </summary>
    public static string BuildAgainstFormerSdk(string name, string source)
    {
        byte[] former = RenamedSdk();
        var references = PlatformReferences(except: [FormerSdkName, typeof(IStrategy).Assembly.GetName().Name!]);
        references.Add(MetadataReference.CreateFromImage(former));
        string dll = Emit(name, source, references);
        File.WriteAllBytes(Path.Combine(Path.GetDirectoryName(dll)!, FormerSdkName + ".dll"), former);
        return dll;
    }

    private static byte[] RenamedSdk()
    {
        using var resolver = new Mono.Cecil.DefaultAssemblyResolver();
        resolver.AddSearchDirectory(AppContext.BaseDirectory);
        using var sdk = Mono.Cecil.AssemblyDefinition.ReadAssembly(typeof(IStrategy).Assembly.Location, new Mono.Cecil.ReaderParameters { AssemblyResolver = resolver });
        sdk.Name.Name = FormerSdkName;
        sdk.MainModule.Name = FormerSdkName + ".dll";
        using var image = new MemoryStream();
        sdk.Write(image);
        return image.ToArray();
    }

    // Every assembly of the runtime and of this test's own dependencies, but the ones named.
    private static List<MetadataReference> PlatformReferences(string[]? except)
    {
        var references = new List<MetadataReference>();
        string trusted = (string)AppContext.GetData("TRUSTED_PLATFORM_ASSEMBLIES")!;
        foreach (string path in trusted.Split(Path.PathSeparator))
        {
            if (except is null || Array.IndexOf(except, Path.GetFileNameWithoutExtension(path)) < 0)
            {
                references.Add(MetadataReference.CreateFromFile(path));
            }
        }

        return references;
    }

    private static string Emit(string name, string source, List<MetadataReference> references)
    {
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
