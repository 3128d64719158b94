namespace URWPGSim2D.Compat.Tests.Common;

/// <summary>
/// Tests that read or change the process's one <see cref="URWPGSim2D.Common.Field"/> (directly or through a mission
/// built from a snapshot) run one after another, never at the same time.
/// </summary>
[CollectionDefinition(Name)]
public sealed class FieldCollection
{
    /// <summary>The collection's name.</summary>
    public const string Name = "The process's Field";
}
