using System.Runtime.CompilerServices;
using System.Runtime.Loader;
using URWPGSim2D.Compat.Retargeting;
using URWPGSim2D.Tests.OldStrategies;

namespace URWPGSim2D.Compat.Tests.Retargeting;

/// <summary>
/// The real DLLs built for the original (<see cref="RealOldDlls"/>) load through
/// <see cref="OriginalAssemblyLoader"/> with every reference bound, and their strategy is the original's
/// <c>IStrategy</c>, answering the team name its IL holds.
/// </summary>
public sealed class RealOldDllLoadTests
{
    public static TheoryData<string> Files() => new(RealOldDlls.All().Select(d => d.File));

    [Theory]
    [MemberData(nameof(Files))]
    public void EveryRealOldDllLoadsWithEveryReferenceBound(string file)
    {
        var dll = RealOldDlls.All().Single(d => d.File == file);
        string path = RealOldDlls.PathOf(file);
        var context = new AssemblyLoadContext("real-old-dll", isCollectible: true);
        try
        {
            var assembly = OriginalAssemblyLoader.Load(context, path);
            var image = OriginalAssemblyLoader.Read(path);
            Assert.NotNull(image.Retargeted);
            Assert.Empty(RetargetedReferenceCheck.Missing(assembly, image.Retargeted!));
            Assert.DoesNotContain(assembly.GetReferencedAssemblies(), r => OriginalReferences.IsOriginal(r.Name));

            var type = assembly.GetType("URWPGSim2D.Strategy.Strategy", throwOnError: true)!;
            foreach (var method in type.GetMethods(System.Reflection.BindingFlags.DeclaredOnly | System.Reflection.BindingFlags.Instance | System.Reflection.BindingFlags.Static | System.Reflection.BindingFlags.Public | System.Reflection.BindingFlags.NonPublic))
            {
                RuntimeHelpers.PrepareMethod(method.MethodHandle); // every body JIT-compiles: every call in it binds
            }

            var strategy = Assert.IsAssignableFrom<StrategyLoader.IStrategy>(Activator.CreateInstance(type));
            if (dll.TeamName is { } name)
            {
                Assert.Equal(name, strategy.GetTeamName());
            }
        }
        finally
        {
            context.Unload();
        }
    }

    [Fact]
    public void TheFolderHoldsTheFourKnownDlls()
    {
        var files = System.IO.Directory.GetFiles(RealOldDlls.Folder, "*.dll").Select(System.IO.Path.GetFileName).ToHashSet();
        Assert.All(RealOldDlls.Known, d => Assert.Contains(d.File, files));
    }

    [Fact]
    public void AFileIsReadOnceAndRetargetedOncePerContent()
    {
        string path = RealOldDlls.PathOf(RealOldDlls.Known[1].File);
        var first = OriginalAssemblyLoader.Read(path);
        var second = OriginalAssemblyLoader.Read(path);
        Assert.Same(first, second);
        Assert.Same(first.Retargeted, second.Retargeted);

        // The same bytes under another name share the retargeted image.
        string copy = OldStrategyCompiler.WriteTemporary("Copy.dll", System.IO.File.ReadAllBytes(path));
        try
        {
            var other = OriginalAssemblyLoader.Read(copy);
            Assert.Equal(first.Sha256, other.Sha256);
            Assert.Same(first.Retargeted, other.Retargeted);
        }
        finally
        {
            System.IO.Directory.Delete(System.IO.Path.GetDirectoryName(copy)!, recursive: true);
        }
    }
}
