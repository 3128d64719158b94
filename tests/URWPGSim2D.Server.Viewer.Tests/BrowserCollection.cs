namespace URWPGSim2D.Server.Viewer.Tests;

/// <summary>The browser tests share one browser and run one after the other (2 cores).</summary>
[CollectionDefinition(Name)]
public sealed class BrowserCollection : ICollectionFixture<Browser>, ICollectionFixture<RecordedMatch>
{
    /// <summary>The collection's name.</summary>
    public const string Name = "browser";
}
