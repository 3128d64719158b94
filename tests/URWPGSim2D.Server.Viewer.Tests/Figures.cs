namespace URWPGSim2D.Server.Viewer.Tests;

/// <summary>
/// Where the tests' screenshots go: docs/figures when asked (scripts/regenerate-docs-outputs.sh
/// --screenshot sets URWPGSIM2D_REGENERATE_DOCS=1), else the test's temporary folder, so the working
/// tree is left alone (a screenshot can differ by a few pixels between machines' fonts).
/// </summary>
internal static class Figures
{
    /// <summary>Takes a screenshot of the page (which must have content) and writes it as <see cref="Write"/> does.</summary>
    public static async Task Shoot(IPage page, string name, string folder)
    {
        byte[] png = await page.ScreenshotAsync(new() { Type = ScreenshotType.Png });
        Assert.True(png.Length > 20_000, $"the screenshot {name} has content");
        Write(name, png, folder);
    }

    /// <summary>Writes <paramref name="png"/> as docs/figures/<paramref name="name"/> when asked, else into <paramref name="folder"/>.</summary>
    public static void Write(string name, byte[] png, string folder)
    {
        bool refresh = Environment.GetEnvironmentVariable("URWPGSIM2D_REGENERATE_DOCS") == "1";
        string figure = Path.Combine(refresh ? Path.Combine(Repository.Root, "docs", "figures") : folder, name);
        if (!File.Exists(figure) || !File.ReadAllBytes(figure).AsSpan().SequenceEqual(png))
        {
            File.WriteAllBytes(figure, png);
        }
    }
}
