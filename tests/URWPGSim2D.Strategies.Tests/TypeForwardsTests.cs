using System.Reflection;

namespace URWPGSim2D.Strategies.Tests;

/// <summary>
/// The SDK's former assembly, <c>URWPGSim2D.Strategy</c>, declares no type and forwards every
/// public type of the SDK to <c>URWPGSim2D.Strategies</c>, so a strategy compiled against the former
/// name finds each type it names.
/// </summary>
public sealed class TypeForwardsTests
{
    private static readonly Assembly Former = Assembly.Load(new AssemblyName("URWPGSim2D.Strategy"));

    [Fact]
    public void EveryPublicTypeOfTheSdkIsForwarded()
    {
        var sdk = typeof(IStrategy).Assembly.GetExportedTypes().Where(t => !t.IsNested).Select(t => t.FullName!).Order().ToList();
        var forwarded = Former.GetForwardedTypes().Where(t => !t.IsNested).Select(t => t.FullName!).Order().ToList();
        Assert.Contains("URWPGSim2D.Strategies.IStrategy", sdk);
        Assert.Equal(sdk, forwarded);
        Assert.All(Former.GetForwardedTypes(), t => Assert.Same(typeof(IStrategy).Assembly, t.Assembly));
    }

    [Fact]
    public void TheFormerAssemblyDeclaresNoTypeOfItsOwn()
    {
        Assert.Empty(Former.GetTypes());
        Assert.Equal(typeof(IStrategy).Assembly.GetName().Version, Former.GetName().Version);
    }

    [Fact]
    public void ATypeNamedInTheFormerAssemblyIsTheSdksType()
    {
        Assert.Same(typeof(Decision), Type.GetType("URWPGSim2D.Strategies.Decision, URWPGSim2D.Strategy", throwOnError: true));
        Assert.Same(typeof(MatchSnapshot), Type.GetType("URWPGSim2D.Strategies.MatchSnapshot, URWPGSim2D.Strategy", throwOnError: true));
    }
}
