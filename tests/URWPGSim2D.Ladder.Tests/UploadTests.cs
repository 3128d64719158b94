using System.IO.Compression;

namespace URWPGSim2D.Ladder.Tests;

/// <summary>Uploads: what lands where, and the hostile ones (paths leaving the folder, oversized, too many files) refused whole.</summary>
public sealed class UploadTests : IDisposable
{
    private readonly string _folder = Directory.CreateTempSubdirectory("urwpg-ladder-upload-").FullName;
    private static readonly LadderLimits Limits = new(MaxUploadBytes: 4096, MaxFiles: 3, MaxUnpackedBytes: 8192);

    public void Dispose() => Directory.Delete(_folder, recursive: true);

    private static UploadedFile Cs(string name, string text = "class A {}") => new(name, Encoding.UTF8.GetBytes(text));

    private static UploadedFile Zip(params (string Name, string Text)[] entries)
    {
        using var stream = new MemoryStream();
        using (var zip = new ZipArchive(stream, ZipArchiveMode.Create, leaveOpen: true))
        {
            foreach (var (name, text) in entries)
            {
                using var writer = new StreamWriter(zip.CreateEntry(name).Open());
                writer.Write(text);
            }
        }

        return new UploadedFile("sources.zip", stream.ToArray());
    }

    private string Target => Path.Combine(_folder, "1");

    [Fact]
    public void OneSourceFileIsItsSpec()
    {
        var (kind, spec) = Uploads.Write([Cs("My.cs")], Target, Limits);
        Assert.Equal((Uploads.SourceFile, Path.Combine(Target, "My.cs")), (kind, spec));
        Assert.Equal("class A {}", File.ReadAllText(spec));
    }

    [Fact]
    public void SeveralSourcesAndAZipAreFolders()
    {
        var (kind, spec) = Uploads.Write([Cs("A.cs"), Cs("B.cs")], Target, Limits);
        Assert.Equal((Uploads.SourceFolder, Path.Combine(Target, "src")), (kind, spec));
        Assert.Equal(["A.cs", "B.cs"], Directory.GetFiles(spec).Select(Path.GetFileName).Order());

        var (zipKind, zipSpec) = Uploads.Write([Zip(("x/A.cs", "class A {}"), ("B.cs", "class B {}"))], Path.Combine(_folder, "2"), Limits);
        Assert.Equal(Uploads.SourceFolder, zipKind);
        Assert.True(File.Exists(Path.Combine(zipSpec, "x", "A.cs")));
        Assert.True(File.Exists(Path.Combine(zipSpec, "B.cs")));
    }

    [Theory]
    [InlineData("../evil.cs")]
    [InlineData("a/../../evil.cs")]
    [InlineData("/etc/evil.cs")]
    [InlineData("..\\evil.cs")]
    public void AnArchivePathLeavingItsFolderRefusesTheWholeUpload(string entry)
    {
        var e = Assert.Throws<UploadException>(() => Uploads.Write([Zip(("Good.cs", "class G {}"), (entry, "class E {}"))], Target, Limits));
        Assert.Contains("leaves its folder", e.Message, StringComparison.Ordinal);
        Assert.False(Directory.Exists(Target)); // nothing half-written
        Assert.False(Directory.Exists(Target + ".part"));
        Assert.Empty(Directory.GetFiles(_folder, "evil.cs", SearchOption.AllDirectories));
        Assert.False(File.Exists(Path.Combine(Path.GetDirectoryName(_folder)!, "evil.cs")));
    }

    [Fact]
    public void OversizedUploadsAndTooManyFilesAreRefused()
    {
        var big = Assert.Throws<UploadException>(() => Uploads.Write([Cs("Big.cs", new string('x', 5000))], Target, Limits));
        Assert.Equal("upload: 5000 bytes, more than the limit of 4096", big.Message);

        var many = Assert.Throws<UploadException>(() => Uploads.Write([Cs("A.cs"), Cs("B.cs"), Cs("C.cs"), Cs("D.cs")], Target, Limits));
        Assert.Equal("upload: 4 files, more than the limit of 3", many.Message);

        // A small archive that unpacks past the limit (a zip bomb in miniature).
        var bomb = Assert.Throws<UploadException>(() => Uploads.Write([Zip(("A.cs", new string(' ', 9000)))], Target, Limits));
        Assert.Contains("unpacks to more than the limit of 8192 bytes", bomb.Message, StringComparison.Ordinal);
        Assert.False(Directory.Exists(Target));
    }

    [Theory]
    [InlineData("../x.cs")]
    [InlineData("a/b.cs")]
    [InlineData("..")]
    public void APlainFileNameHasNoFolderPart(string name)
    {
        var e = Assert.Throws<UploadException>(() => Uploads.Write([Cs(name)], Target, Limits));
        Assert.StartsWith("upload: file name", e.Message, StringComparison.Ordinal);
    }

    [Fact]
    public void OtherFilesAreRefused()
    {
        var e = Assert.Throws<UploadException>(() => Uploads.Write([new UploadedFile("run.sh", [1, 2])], Target, Limits));
        Assert.Equal("upload: \"run.sh\" is not a .cs file (give .cs files, one .zip of sources or one .dll)", e.Message);
    }
}
