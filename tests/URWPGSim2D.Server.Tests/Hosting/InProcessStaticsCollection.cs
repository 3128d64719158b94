namespace URWPGSim2D.Server.Tests.Hosting;

/// <summary>
/// Tests that compare a match played with strategies in the server's process (<c>--isolation none</c>)
/// to the same match in strategy hosts. In one process, original-API strategies share the
/// compatibility assembly's statics (<c>Field.Instance()</c>, which each call sets to its match's
/// field), so another test playing another item at the same time in this test process could change
/// what an in-process strategy sees. The server never plays two items at once in one process; these
/// tests run alone so that the test process does not either.
/// </summary>
[CollectionDefinition(Name, DisableParallelization = true)]
public sealed class InProcessStaticsCollection
{
    /// <summary>The collection's name.</summary>
    public const string Name = "in-process statics";
}
