using System.Collections.Immutable;
using System.Reflection;
using System.Reflection.Metadata;
using System.Reflection.PortableExecutable;
using System.Runtime.CompilerServices;
using System.Runtime.Loader;
using System.Security.Cryptography;
using Microsoft.CodeAnalysis;
using URWPGSim2D.Compat.Retargeting;
using URWPGSim2D.Tests.OldStrategies;

namespace URWPGSim2D.Compat.Tests.Retargeting;

/// <summary>
/// DLLs in the shape of those built for the original (compiled here: <see cref="OldStrategyCompiler"/>)
/// load through <see cref="OriginalAssemblyLoader"/>, bind every member of the original's API the
/// compatibility assembly provides, and leave their file alone; native code and missing API are refused.
/// </summary>
public sealed class OriginalAssemblyLoaderTests
{
    private static readonly Lazy<byte[]> ToucherImage = new(() =>
        OldStrategyCompiler.Compile("OldToucher", Platform.X86, OldStrategySources.Toucher, ApiToucher.Source()));

    private static AssemblyLoadContext Context() => new("old-dll-test", isCollectible: true);

    // Runs test with a fresh collectible context, then unloads it and deletes the temporary folder of the DLL at path.
    private static void InFreshContext(string path, Action<AssemblyLoadContext> test)
    {
        var context = Context();
        try
        {
            test(context);
        }
        finally
        {
            context.Unload();
            Directory.Delete(Path.GetDirectoryName(path)!, recursive: true);
        }
    }

    [Fact]
    public void TheTestDllsHaveTheShapeOfTheOriginalsDlls()
    {
        using var pe = new PEReader(ImmutableArray.Create(ToucherImage.Value));
        Assert.Equal(Machine.I386, pe.PEHeaders.CoffHeader.Machine);
        Assert.Equal(PEMagic.PE32, pe.PEHeaders.PEHeader!.Magic);
        Assert.Equal(CorFlags.ILOnly | CorFlags.Requires32Bit, pe.PEHeaders.CorHeader!.Flags);
        var metadata = pe.GetMetadataReader();
        Assert.Equal("v2.0.50727", metadata.MetadataVersion);
        var references = metadata.AssemblyReferences.Select(h => metadata.GetAssemblyReference(h))
            .ToDictionary(r => metadata.GetString(r.Name), r => (r.Version, Token: Convert.ToHexString(metadata.GetBlobBytes(r.PublicKeyOrToken)).ToLowerInvariant()));
        Assert.Equal((new Version(2, 0, 0, 0), "b77a5c561934e089"), references["mscorlib"]);
        Assert.Equal((new Version(3, 1, 0, 0), "6d5c3888ef60e27d"), references["Microsoft.Xna.Framework"]);
        foreach (string name in new[] { "URWPGSim2D.Common", "URWPGSim2D.StrategyLoader", "URWPGSim2D.StrategyHelper", "URWPGSim2D.Core" })
        {
            Assert.Equal((new Version(1, 2, 123, 20110), "04f000b8db128100"), references[name]);
        }

        Assert.Contains(metadata.TypeDefinitions.Select(h => metadata.GetTypeDefinition(h)),
            t => metadata.GetString(t.Namespace) == "URWPGSim2D.Strategy" && metadata.GetString(t.Name) == "Strategy");
    }

    [Fact]
    public void AnOldDllThatTouchesEveryMemberOfTheOriginalsApiLoadsAndBindsThemAll()
    {
        string path = OldStrategyCompiler.WriteTemporary("OldToucher.dll", ToucherImage.Value);
        InFreshContext(path, context =>
        {
            var assembly = OriginalAssemblyLoader.Load(context, path);
            Assert.Equal(string.Empty, assembly.Location);
            Assert.DoesNotContain(assembly.GetReferencedAssemblies(), r => OriginalReferences.IsOriginal(r.Name));
            var touch = assembly.GetType("OldApi.Toucher")!.GetMethod("Touch")!;
            RuntimeHelpers.PrepareMethod(touch.MethodHandle);
            Assert.Equal(0, touch.Invoke(null, [false]));
            var strategy = (StrategyLoader.IStrategy)Activator.CreateInstance(assembly.GetType("URWPGSim2D.Strategy.Strategy")!)!;
            Assert.Equal("Old toucher 0", strategy.GetTeamName());
            // A floor against the stand-ins silently leaving members out (378 when written, 443 with XNA's vector statics, 479 with the original's further Common members, 651 with XNA's Matrix, Quaternion and transforms, 657 with Field's rectangles and SysConfig).
            Assert.True(ApiToucher.Members >= 657, $"{ApiToucher.Members} members touched");
        });
    }

    [Fact]
    public void TheFileIsNeverChangedAndNothingIsWrittenBesideIt()
    {
        byte[] image = OldStrategyCompiler.Compile("OldDribbler", Platform.X86, OldStrategySources.Dribbler);
        string path = OldStrategyCompiler.WriteTemporary("OldDribbler.dll", image);
        string folder = Path.GetDirectoryName(path)!;
        byte[] before = SHA256.HashData(File.ReadAllBytes(path));
        var written = File.GetLastWriteTimeUtc(path);
        var context = Context();
        try
        {
            var assembly = OriginalAssemblyLoader.Load(context, path);
            Assert.NotNull(assembly.GetType("URWPGSim2D.Strategy.Strategy"));
            Assert.Equal(before, SHA256.HashData(File.ReadAllBytes(path)));
            Assert.Equal(written, File.GetLastWriteTimeUtc(path));
            Assert.Equal(["OldDribbler.dll"], Directory.GetFiles(folder).Select(Path.GetFileName));
        }
        finally
        {
            context.Unload();
            Directory.Delete(folder, recursive: true);
        }
    }

    [Fact]
    public void AnAnyCpuOldDllLoadsToo()
    {
        byte[] image = OldStrategyCompiler.Compile("OldAnyCpu", Platform.AnyCpu, OldStrategySources.Dribbler);
        using (var pe = new PEReader(ImmutableArray.Create(image)))
        {
            Assert.Equal(CorFlags.ILOnly, pe.PEHeaders.CorHeader!.Flags);
        }

        string path = OldStrategyCompiler.WriteTemporary("OldAnyCpu.dll", image);
        InFreshContext(path, context =>
        {
            var type = OriginalAssemblyLoader.Load(context, path).GetType("URWPGSim2D.Strategy.Strategy")!;
            Assert.Equal("Old dribbler", ((StrategyLoader.IStrategy)Activator.CreateInstance(type)!).GetTeamName());
        });
    }

    [Fact]
    public void WithoutRetargetingTheRuntimeRefusesTheSameDll()
    {
        // The two failures users met: the x86 image, and (AnyCPU) the original's assembly names.
        string x86 = OldStrategyCompiler.WriteTemporary("OldX86.dll", OldStrategyCompiler.Compile("OldX86", Platform.X86, OldStrategySources.Dribbler));
        string any = OldStrategyCompiler.WriteTemporary("OldAny.dll", OldStrategyCompiler.Compile("OldAny", Platform.AnyCpu, OldStrategySources.Dribbler));
        var context = Context();
        try
        {
            var e = Assert.Throws<FileLoadException>(() => context.LoadFromAssemblyPath(x86));
            Assert.Contains("architecture", e.Message, StringComparison.Ordinal);
            var assembly = context.LoadFromAssemblyPath(any);
            var missing = Assert.Throws<FileNotFoundException>(() => assembly.GetType("URWPGSim2D.Strategy.Strategy", throwOnError: true));
            Assert.Contains("URWPGSim2D.StrategyLoader, Version=1.2.123.20110", missing.Message, StringComparison.Ordinal);
        }
        finally
        {
            context.Unload();
            Directory.Delete(Path.GetDirectoryName(x86)!, recursive: true);
            Directory.Delete(Path.GetDirectoryName(any)!, recursive: true);
        }
    }

    [Fact]
    public void ADllHoldingNativeCodeIsRefusedInOneLine()
    {
        byte[] image = OldStrategyCompiler.Compile("OldMixed", Platform.X86, OldStrategySources.Dribbler);
        ClearILOnly(image);
        string path = OldStrategyCompiler.WriteTemporary("OldMixed.dll", image);
        try
        {
            var e = Assert.Throws<BadImageFormatException>(() => OriginalAssemblyLoader.Load(Context(), path));
            Assert.Contains("native code", e.Message, StringComparison.Ordinal);
            Assert.DoesNotContain('\n', e.Message);
        }
        finally
        {
            Directory.Delete(Path.GetDirectoryName(path)!, recursive: true);
        }
    }

    [Fact]
    public void ADllUsingApiTheCompatibilityAssemblyLacksIsRefusedNamingIt()
    {
        const string UsesVector4 = """
            namespace Uses
            {
                public class Vectors
                {
                    public object Make() { return Microsoft.Xna.Framework.Vector4.One; }
                }
            }
            """;
        string path = OldStrategyCompiler.WriteTemporary("OldVector4.dll", OldStrategyCompiler.CompileWithXnaVector4("OldVector4", OldStrategySources.Dribbler, UsesVector4));
        InFreshContext(path, context =>
        {
            var e = Assert.Throws<FileLoadException>(() => OriginalAssemblyLoader.Load(context, path));
            Assert.Contains("Microsoft.Xna.Framework.Vector4", e.Message, StringComparison.Ordinal);
            Assert.DoesNotContain('\n', e.Message);
        });
    }

    [Fact]
    public void ADllReferencingAnAssemblyThatIsNotHereIsRefusedNamingTheAssembly()
    {
        const string UsesMatch = "namespace Uses { public class Scores { public int Get() { return URWPGSim2D.Match.Polo.Score(); } } }";
        const string Match = """
            [assembly: System.Reflection.AssemblyVersion("1.2.123.20110")]
            namespace URWPGSim2D.Match { public static class Polo { public static int Score() { return 0; } } }
            """;
        byte[] image = OldStrategyCompiler.CompileWithExtraAssembly("URWPGSim2D.Match", OldStrategyCompiler.OriginalToken, Match, "OldScores", OldStrategySources.Dribbler, UsesMatch);
        string path = OldStrategyCompiler.WriteTemporary("OldScores.dll", image);
        InFreshContext(path, context =>
        {
            var e = Assert.Throws<FileLoadException>(() => OriginalAssemblyLoader.Load(context, path));
            Assert.Equal("it uses assemblies that are not here (URWPGSim2D.Match): URWPGSim2D.Match.Polo, URWPGSim2D.Match.Polo.Score", e.Message);
        });
    }

    [Fact]
    public void AnOldDllReadsItsOwnResources()
    {
        // A .resources blob as .NET Framework 2.0 wrote it: its header names mscorlib 2.0.0.0's reader and set.
        using var written = new MemoryStream();
        using (var writer = new System.Resources.ResourceWriter(written))
        {
            writer.AddResource("TeamName", "红队 from resources");
        }

        byte[] blob = written.ToArray();
        byte[] now = System.Text.Encoding.ASCII.GetBytes("Version=4.0.0.0");
        byte[] then = System.Text.Encoding.ASCII.GetBytes("Version=2.0.0.0");
        int replaced = 0;
        for (int i = blob.AsSpan().IndexOf(now); i >= 0; i = blob.AsSpan().IndexOf(now))
        {
            then.CopyTo(blob, i);
            replaced++;
        }

        Assert.True(replaced >= 1, "the header names the reader's assembly version");
        const string Named = """
            namespace URWPGSim2D.Strategy
            {
                public class Strategy : System.MarshalByRefObject, URWPGSim2D.StrategyLoader.IStrategy
                {
                    public string GetTeamName() { return new System.Resources.ResourceManager("OldRes.Strings", typeof(Strategy).Assembly).GetString("TeamName"); }
                    public URWPGSim2D.Common.Decision[] GetDecision(URWPGSim2D.Common.Mission mission, int teamId) { return null; }
                }
            }
            """;
        string path = OldStrategyCompiler.WriteTemporary("OldRes.dll", OldStrategyCompiler.CompileWithResources("OldRes", [("OldRes.Strings.resources", blob)], Named));
        InFreshContext(path, context =>
        {
            var type = OriginalAssemblyLoader.Load(context, path).GetType("URWPGSim2D.Strategy.Strategy")!;
            Assert.Equal("红队 from resources", ((StrategyLoader.IStrategy)Activator.CreateInstance(type)!).GetTeamName());
        });
    }

    [Fact]
    public void AnAssemblyBuiltForThisRuntimeLoadsFromItsFileUnchanged()
    {
        string path = typeof(OriginalAssemblyLoaderTests).Assembly.Location;
        var context = Context();
        try
        {
            Assert.Equal(path, OriginalAssemblyLoader.Load(context, path).Location);
        }
        finally
        {
            context.Unload();
        }
    }

    /// <summary>Clears the CLR header's ILONLY flag, as in an image holding native code.</summary>
    private static void ClearILOnly(byte[] image)
    {
        using var pe = new PEReader(ImmutableArray.Create(image));
        var directory = pe.PEHeaders.PEHeader!.CorHeaderTableDirectory;
        Assert.True(pe.PEHeaders.TryGetDirectoryOffset(directory, out int header));
        int flags = header + 16;
        image[flags] &= unchecked((byte)~(int)CorFlags.ILOnly);
    }
}
