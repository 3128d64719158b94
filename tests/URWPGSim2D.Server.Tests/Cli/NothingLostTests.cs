namespace URWPGSim2D.Server.Tests.Cli;

/// <summary>An existing results, trace or page file is never replaced unless --force: exit 2, one line, the file untouched.</summary>
public sealed class NothingLostTests() : TempFolderTest("urwpg-nothing-lost-")
{
    private const string Kept = "a finished file\n";

    [Theory]
    [InlineData("--trace", "run", "--cycles", "3")]
    [InlineData("--html", "run", "--cycles", "3")]
    [InlineData("--results", "run", "--cycles", "3", "--batch", "1", "--threads", "1")]
    public void RunRefusesToReplaceAFileWithoutForce(string option, params string[] command)
    {
        string file = Existing("kept.out");
        var refused = CliRun.Of(string.Empty, [.. command, option, file]);
        Assert.Equal(2, refused.ExitCode);
        Assert.Equal(string.Empty, refused.Stdout);
        Assert.Equal($"{option}: \"{file}\" exists; give --force to replace it\n", refused.Stderr);
        Assert.Equal(Kept, File.ReadAllText(file));

        var forced = CliRun.Of(string.Empty, [.. command, option, file, "--force"]);
        Assert.Equal(0, forced.ExitCode);
        Assert.NotEqual(Kept, File.ReadAllText(file));
    }

    [Fact]
    public void ViewAndMergeRefuseToReplaceAFileWithoutForce()
    {
        string trace = Path.Combine(Folder, "t.jsonl");
        string results = Path.Combine(Folder, "r.jsonl");
        Assert.Equal(0, CliRun.Of(string.Empty, "run", "--cycles", "3", "--trace", trace).ExitCode);
        Assert.Equal(0, CliRun.Of(string.Empty, "run", "--cycles", "3", "--batch", "1", "--threads", "1", "--results", results).ExitCode);

        string page = Existing("page.html");
        var view = CliRun.Of(string.Empty, "view", trace, "--html", page);
        Assert.Equal((2, $"--html: \"{page}\" exists; give --force to replace it\n"), (view.ExitCode, view.Stderr));
        Assert.Equal(Kept, File.ReadAllText(page));
        Assert.Equal(0, CliRun.Of(string.Empty, "view", trace, "--html", page, "--force").ExitCode);
        Assert.StartsWith("<!DOCTYPE html>", File.ReadAllText(page), StringComparison.OrdinalIgnoreCase);

        string merged = Existing("all.jsonl");
        var merge = CliRun.Of(string.Empty, "merge", "--out", merged, results);
        Assert.Equal((2, string.Empty, $"--out: \"{merged}\" exists; give --force to replace it\n"), (merge.ExitCode, merge.Stdout, merge.Stderr));
        Assert.Equal(Kept, File.ReadAllText(merged));
        Assert.Equal(0, CliRun.Of(string.Empty, "merge", "--out", merged, "--force", results).ExitCode);
        Assert.NotEqual(Kept, File.ReadAllText(merged));
    }

    private string Existing(string name)
    {
        string path = Path.Combine(Folder, name);
        File.WriteAllText(path, Kept);
        return path;
    }
}
