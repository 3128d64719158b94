using System.Net.Http.Headers;
using System.Threading;
using URWPGSim2D.Ladder.Web;

namespace URWPGSim2D.Ladder.Tests;

/// <summary>A ladder service in this process on a free loopback port, over a fresh data folder (or a given one, kept); HTTP helpers; waits on conditions with generous bounds.</summary>
public sealed class LadderHost : IAsyncDisposable
{
    public const string AdminToken = "organiser-secret-token";

    private readonly bool _ownFolder;

    private LadderHost(LadderServer server, string folder, bool ownFolder)
    {
        Server = server;
        Folder = folder;
        _ownFolder = ownFolder;
        Http = new HttpClient { BaseAddress = new Uri(server.Url), Timeout = TimeSpan.FromMinutes(5) };
    }

    public LadderServer Server { get; }

    public string Folder { get; }

    public HttpClient Http { get; }

    public static async Task<LadderHost> StartAsync(int workers, string item = "polo-1v1", LadderLimits? limits = null, URWPGSim2D.Hosting.HostSettings? hostSettings = null, string? folder = null)
    {
        bool own = folder is null;
        folder ??= Directory.CreateTempSubdirectory("urwpg-ladder-").FullName;
        var settings = new LadderSettings
        {
            Item = item, Cycles = 600, DataDir = folder, Port = 0, AdminToken = AdminToken, Workers = workers, Limits = limits ?? new LadderLimits(),
            HostSettings = hostSettings ?? URWPGSim2D.Hosting.HostSettings.Default,
        };
        return new LadderHost(await LadderServer.StartAsync(settings, _ => { }), folder, own);
    }

    public async Task<(int Status, JsonElement Body)> Send(HttpMethod method, string path, string? token = null, string? json = null, HttpContent? content = null, string? origin = null)
    {
        using var request = new HttpRequestMessage(method, path);
        if (token is not null)
        {
            request.Headers.Authorization = new AuthenticationHeaderValue("Bearer", token);
        }

        if (origin is not null)
        {
            request.Headers.Add("Origin", origin);
        }

        request.Content = content ?? (json is null ? null : new StringContent(json, Encoding.UTF8, "application/json"));
        using var response = await Http.SendAsync(request);
        string text = await response.Content.ReadAsStringAsync();
        using var document = JsonDocument.Parse(text);
        return ((int)response.StatusCode, document.RootElement.Clone());
    }

    public Task<(int Status, JsonElement Body)> Get(string path, string? token = null) => Send(HttpMethod.Get, path, token);

    /// <summary>Waits until <paramref name="condition"/> holds, asking again after each answer; fails after <paramref name="minutes"/>.</summary>
    public static async Task Until(Func<Task<bool>> condition, string what, double minutes = 5)
    {
        var deadline = DateTime.UtcNow + TimeSpan.FromMinutes(minutes);
        while (!await condition())
        {
            if (DateTime.UtcNow > deadline)
            {
                throw new TimeoutException($"not within {minutes} minutes: {what}");
            }

            await Task.Delay(100);
        }
    }

    public async ValueTask DisposeAsync()
    {
        Http.Dispose();
        await Server.DisposeAsync();
        if (!_ownFolder)
        {
            return;
        }

        for (int attempt = 0; ; attempt++)
        {
            try
            {
                Directory.Delete(Folder, recursive: true);
                return;
            }
            catch (IOException) when (attempt < 5)
            {
                Thread.Yield();
            }
        }
    }
}
