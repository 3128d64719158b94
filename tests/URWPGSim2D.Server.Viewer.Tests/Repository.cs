namespace URWPGSim2D.Server.Viewer.Tests;

/// <summary>The repository's root folder (the one with the solution file), found from the test binaries upward.</summary>
internal static class Repository
{
    public static string Root { get; } = Find();

    private static string Find()
    {
        for (var dir = new DirectoryInfo(AppContext.BaseDirectory); dir is not null; dir = dir.Parent)
        {
            if (File.Exists(Path.Combine(dir.FullName, "URWPGSim2D.Collision.sln")))
            {
                return dir.FullName;
            }
        }

        throw new InvalidOperationException("the repository root (URWPGSim2D.Collision.sln) is not above " + AppContext.BaseDirectory);
    }
}
