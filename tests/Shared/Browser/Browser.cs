namespace URWPGSim2D.Server.Viewer.Tests;

/// <summary>
/// One headless Debian Chromium (/usr/bin/chromium, installed by .ci/install-chromium) driven by
/// Playwright, shared by every browser test. A missing browser fails the tests with a message
/// naming the install script — it never skips them.
/// </summary>
public sealed class Browser : IAsyncLifetime
{
    /// <summary>Where Debian puts Chromium.</summary>
    public const string ChromiumPath = "/usr/bin/chromium";

    /// <summary>
    /// How long any wait of these tests (for a page, a server, a frame, a cycle) may last, ms. No test
    /// waits for a time to pass: each waits for something to happen, and this bound is reached only
    /// when it never does (a hang), never by a slow or busy machine, so no outcome depends on speed.
    /// </summary>
    public const int HangMs = 300_000;

    private IPlaywright? _playwright;
    private IBrowser? _browser;

    /// <summary>The running browser.</summary>
    public IBrowser Instance => _browser ?? throw new InvalidOperationException("the browser did not start");

    /// <inheritdoc/>
    public async Task InitializeAsync()
    {
        if (!File.Exists(ChromiumPath))
        {
            throw new InvalidOperationException($"Chromium is missing at {ChromiumPath}: run `bash .ci/install-chromium` (as root; it installs Debian's chromium package) before the browser tests");
        }

        _playwright = await Playwright.CreateAsync();
        _browser = await _playwright.Chromium.LaunchAsync(new BrowserTypeLaunchOptions
        {
            ExecutablePath = ChromiumPath,
            Headless = true,
            Args = ["--no-sandbox", "--disable-gpu", "--disable-dev-shm-usage"],
        });
    }

    /// <inheritdoc/>
    public async Task DisposeAsync()
    {
        if (_browser is not null)
        {
            await _browser.DisposeAsync();
        }

        _playwright?.Dispose();
    }

    /// <summary>A new page (1280 × 800, device pixel ratio 1) that records console errors and uncaught page errors.</summary>
    public async Task<(IPage Page, List<string> Errors)> NewPageAsync()
    {
        var context = await Instance.NewContextAsync(new BrowserNewContextOptions { ViewportSize = new ViewportSize { Width = 1280, Height = 800 }, DeviceScaleFactor = 1 });
        context.SetDefaultTimeout(HangMs); // clicks and waits for elements, too, are bounded only by a hang
        var page = await context.NewPageAsync();
        var errors = new List<string>();
        page.Console += (_, m) =>
        {
            if (m.Type is "error")
            {
                lock (errors)
                {
                    errors.Add($"console {m.Type}: {m.Text}");
                }
            }
        };
        page.PageError += (_, e) =>
        {
            lock (errors)
            {
                errors.Add($"page error: {e}");
            }
        };
        return (page, errors);
    }
}
