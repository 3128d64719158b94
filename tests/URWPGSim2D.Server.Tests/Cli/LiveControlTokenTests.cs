using System.Net.Http;
using System.Text.RegularExpressions;

namespace URWPGSim2D.Server.Tests.Cli;

/// <summary>
/// <c>run --live --host 0.0.0.0</c> in a classroom: the banner names addresses students can open (never
/// 0.0.0.0), viewers there only watch (<c>POST /control</c> is 403 without the control token), and the
/// <c>control:</c> link the server prints is the one that steers. On loopback nothing changes: every
/// viewer controls, with no token.
/// </summary>
public sealed partial class LiveControlTokenTests
{
    [Fact]
    public async Task OnEveryInterfaceViewersWatchAndOnlyTheControlLinkSteers()
    {
        int port = LiveRunTests.FreePort();
        var (output, stop, served) = await Start("the addresses above only watch)\n", "--host", "0.0.0.0", "--port", port.ToString(CultureInfo.InvariantCulture));
        try
        {
            string banner = output.ToString();
            Assert.DoesNotContain("0.0.0.0", banner, StringComparison.Ordinal);
            Assert.StartsWith("live view: http://", banner, StringComparison.Ordinal);
            var control = ControlLine().Match(banner);
            Assert.True(control.Success, banner);
            Assert.Equal(port.ToString(CultureInfo.InvariantCulture), control.Groups[1].Value);
            string token = control.Groups[2].Value;
            string home = $"http://127.0.0.1:{port}/";

            using var http = new HttpClient();
            var refused = await http.PostAsync(home + "control?action=step", new StringContent(string.Empty));
            Assert.Equal(HttpStatusCode.Forbidden, refused.StatusCode);
            Assert.StartsWith("view only", await refused.Content.ReadAsStringAsync(), StringComparison.Ordinal);
            Assert.Equal(HttpStatusCode.Forbidden, (await http.PostAsync(home + "control?action=step&token=" + new string('0', 32), new StringContent(string.Empty))).StatusCode);
            Assert.Equal("{\"control\":false}", await http.GetStringAsync(home + "access"));

            Assert.Equal(HttpStatusCode.NoContent, (await http.PostAsync(home + "control?action=step&token=" + token, new StringContent(string.Empty))).StatusCode);
            Assert.Equal("{\"control\":true}", await http.GetStringAsync(home + "access?token=" + token));
        }
        finally
        {
            stop.Cancel();
            Assert.Equal(0, await served);
        }
    }

    [Fact]
    public async Task OnLoopbackEveryViewerControlsWithNoToken()
    {
        int port = LiveRunTests.FreePort();
        var (output, stop, served) = await Start($":{port}/\n", "--port", port.ToString(CultureInfo.InvariantCulture));
        try
        {
            Assert.Equal($"live view: http://127.0.0.1:{port}/\n", output.ToString());
            using var http = new HttpClient();
            string home = $"http://127.0.0.1:{port}/";
            Assert.Equal(HttpStatusCode.NoContent, (await http.PostAsync(home + "control?action=step", new StringContent(string.Empty))).StatusCode);
            Assert.Equal("{\"control\":true}", await http.GetStringAsync(home + "access"));
        }
        finally
        {
            stop.Cancel();
            Assert.Equal(0, await served);
        }
    }

    [Theory]
    [InlineData("127.0.0.1", true)]
    [InlineData("127.0.0.2", true)]
    [InlineData("localhost", true)]
    [InlineData("::1", true)]
    [InlineData("[::1]", true)]
    [InlineData("0.0.0.0", false)]
    [InlineData("192.168.1.20", false)]
    [InlineData("classroom-pc", false)]
    public void OnlyLoopbackAddressesAreThisMachineAlone(string host, bool loopback) =>
        Assert.Equal(loopback, LiveRun.IsLoopback(host));

    // Serves a paused default match; returns once the banner's end (bannerEnd) is printed (the listening callback prints its first line as run does).
    private static async Task<(LiveRunTests.SignallingWriter Output, CancellationTokenSource Stop, Task<int> Served)> Start(string bannerEnd, params string[] extra)
    {
        var options = RunOptions.Parse(["--live", "--paused", "--cycles", "50", .. extra]);
        var output = new LiveRunTests.SignallingWriter(bannerEnd);
        var console = new CliConsole(new StringReader(string.Empty), output, new StringWriter());
        var stop = new CancellationTokenSource();
        var served = Task.Run(() => LiveRun.Serve(options, DefaultScenario.Load(), new TeamStrategy?[2], console, stop.Token, url => console.Out.WriteLine($"live view: {url}")));
        Assert.True(await Task.WhenAny(output.Seen, served, Task.Delay(60_000)) == output.Seen, "the live server did not print its banner: " + output);
        return (output, stop, served);
    }

    [GeneratedRegex(@"\ncontrol: http://127\.0\.0\.1:([0-9]+)/\?token=([0-9a-f]{32}) \(this link alone can pause, restart and start matches: keep it to yourself; the addresses above only watch\)\n")]
    private static partial Regex ControlLine();
}
