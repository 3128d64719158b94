using System;
using System.IO;

namespace URWPGSim2D.Testing;

/// <summary>
/// A test class with a fresh folder of its own under the system's temporary folder: made before each
/// test (xUnit makes one instance a test) and deleted, with all that the test wrote in it, after it.
/// </summary>
public abstract class TempFolderTest : IDisposable
{
    /// <summary>Makes the folder, its name starting with <paramref name="prefix"/>.</summary>
    protected TempFolderTest(string prefix) => Folder = Directory.CreateTempSubdirectory(prefix).FullName;

    /// <summary>The test's own folder (its full path).</summary>
    protected string Folder { get; }

    /// <summary>Deletes the folder and everything in it.</summary>
    public void Dispose()
    {
        Directory.Delete(Folder, recursive: true);
        GC.SuppressFinalize(this);
    }
}
