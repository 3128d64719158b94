using System;
using System.Collections.Generic;
using System.IO;
using System.IO.Compression;
using System.Linq;
using System.Net.Http;
using System.Net.Http.Headers;
using System.Text;
using System.Text.Encodings.Web;
using System.Text.Json;
using System.Threading.Tasks;

namespace URWPGSim2D.Ladder;

/// <summary>
/// The ladder's API from a program: what <c>urwpgsim2d ladder team add</c>, <c>ladder submit</c> and
/// the organiser's commands send. A refusal of the service (its one-line JSON error) or an unreachable
/// service throws <see cref="LadderInputException"/> with that line; a refusal of the ladder named
/// (<c>ladder: …</c>) reads <c>--ladder: …</c>, the option that names it.
/// </summary>
public sealed class LadderClient : IDisposable
{
    private readonly HttpClient _http;
    private readonly string _ladder;

    /// <summary>A client of the service at <paramref name="server"/> (e.g. <c>http://127.0.0.1:5080/</c>) about its only ladder.</summary>
    /// <param name="server">The service's address.</param>
    /// <param name="token">The organiser's or a team's token, sent as <c>Authorization: Bearer</c>.</param>
    public LadderClient(string server, string token)
        : this(server, token, null)
    {
    }

    /// <summary>A client of the service at <paramref name="server"/> about the ladder <paramref name="ladder"/> names.</summary>
    /// <param name="server">The service's address.</param>
    /// <param name="token">The organiser's or a team's token, sent as <c>Authorization: Bearer</c> (empty: none, for what anyone may read).</param>
    /// <param name="ladder">The ladder's id, or its item when one ladder plays it; null: the service's only ladder.</param>
    public LadderClient(string server, string token, string? ladder)
    {
        _ladder = string.IsNullOrEmpty(ladder) ? string.Empty : "?ladder=" + Uri.EscapeDataString(ladder);
        ArgumentNullException.ThrowIfNull(server);
        ArgumentNullException.ThrowIfNull(token);
        if (!Uri.TryCreate(server.EndsWith('/') ? server : server + "/", UriKind.Absolute, out var uri) || uri.Scheme is not ("http" or "https"))
        {
            throw new LadderInputException($"--server must be an http:// or https:// address, got {Engine.Messages.MessageText.Quote(server)}");
        }

        _http = new HttpClient { BaseAddress = uri, Timeout = TimeSpan.FromMinutes(10) };
        if (token.Length > 0)
        {
            _http.DefaultRequestHeaders.Authorization = new AuthenticationHeaderValue("Bearer", token);
        }
    }

    /// <summary>Adds a team (a house entrant playing <paramref name="strategy"/> when given); returns its name and token.</summary>
    /// <param name="name">The team's name.</param>
    /// <param name="strategy">demo, chase-ball or idle; null for a team that submits its own.</param>
    public async Task<(string Name, string Token)> AddTeamAsync(string name, string? strategy)
    {
        string body = Json(w =>
        {
            w.WriteStartObject();
            w.WriteString("name", name);
            if (strategy is not null)
            {
                w.WriteString("strategy", strategy);
            }

            w.WriteEndObject();
        });
        using var answer = await Send(() => _http.PostAsync("api/teams" + _ladder, new StringContent(body, Encoding.UTF8, "application/json")));
        return (answer.RootElement.GetProperty("name").GetString()!, answer.RootElement.GetProperty("token").GetString()!);
    }

    /// <summary>Starts the final round: every pair of the top <paramref name="top"/> plays <paramref name="rounds"/> matches; returns the finalists and the matches queued.</summary>
    /// <param name="top">How many of the highest-ranked teams play the final.</param>
    /// <param name="rounds">Matches of each pair.</param>
    public async Task<(IReadOnlyList<string> Teams, int Matches)> StartFinalAsync(int top, int rounds)
    {
        string body = Json(w =>
        {
            w.WriteStartObject();
            w.WriteNumber("top", top);
            w.WriteNumber("rounds", rounds);
            w.WriteEndObject();
        });
        using var answer = await Send(() => _http.PostAsync("api/final" + _ladder, new StringContent(body, Encoding.UTF8, "application/json")));
        var final = answer.RootElement.GetProperty("final");
        return ([.. final.GetProperty("teams").EnumerateArray().Select(t => t.GetString()!)], final.GetProperty("matches").GetInt32());
    }

    /// <summary>Creates a ladder: its item, the length of its matches in cycles (600 a minute) and the seed of its match 0 (match N plays seed <paramref name="firstSeed"/> + N).</summary>
    /// <param name="item">The item (its slug), one of two teams.</param>
    /// <param name="cycles">Cycles per match.</param>
    /// <param name="firstSeed">The first seed.</param>
    public async Task<LadderSummary> CreateLadderAsync(string item, int cycles, ulong firstSeed)
    {
        string body = Json(w =>
        {
            w.WriteStartObject();
            w.WriteString("item", item);
            w.WriteNumber("cycles", cycles);
            w.WriteNumber("firstSeed", firstSeed);
            w.WriteEndObject();
        });
        using var answer = await Send(() => _http.PostAsync("api/ladders", new StringContent(body, Encoding.UTF8, "application/json")));
        return LadderSummary.Of(answer.RootElement);
    }

    /// <summary>The service's ladders, by id.</summary>
    public async Task<IReadOnlyList<LadderSummary>> LaddersAsync()
    {
        using var answer = await Send(() => _http.GetAsync("api/ladders"));
        return [.. answer.RootElement.GetProperty("ladders").EnumerateArray().Select(LadderSummary.Of)];
    }

    /// <summary>Pauses or resumes the ladder's ranked play; returns the ladder.</summary>
    /// <param name="paused">True to pause, false to resume.</param>
    public async Task<LadderSummary> SetPausedAsync(bool paused)
    {
        using (await Send(() => _http.PostAsync((paused ? "api/ladder/pause" : "api/ladder/resume") + _ladder, new StringContent("{}", Encoding.UTF8, "application/json"))))
        {
        }

        using var answer = await Send(() => _http.GetAsync("api/ladder" + _ladder));
        return LadderSummary.Of(answer.RootElement);
    }

    /// <summary>
    /// Submits <paramref name="path"/>: a folder of <c>.cs</c> files (sent as one .zip of its sources),
    /// one <c>.cs</c> file or a DLL. Returns the submission's id, whether it checked, and its log.
    /// </summary>
    /// <param name="path">The strategy.</param>
    public async Task<(long Id, bool Ok, string Log)> SubmitAsync(string path)
    {
        ArgumentNullException.ThrowIfNull(path);
        using var form = new MultipartFormDataContent();
        if (Directory.Exists(path))
        {
            form.Add(new ByteArrayContent(ZipSources(path)), "file", "sources.zip");
        }
        else if (File.Exists(path) && (path.EndsWith(".cs", StringComparison.OrdinalIgnoreCase) || path.EndsWith(".dll", StringComparison.OrdinalIgnoreCase)))
        {
            form.Add(new ByteArrayContent(File.ReadAllBytes(path)), "file", Path.GetFileName(path));
        }
        else
        {
            throw new LadderInputException($"PATH must be a folder of .cs files, a .cs file or a .dll, got {Engine.Messages.MessageText.Quote(path)}");
        }

        using var answer = await Send(() => _http.PostAsync("api/submissions" + _ladder, form), accept422: true);
        var root = answer.RootElement;
        return (root.GetProperty("id").GetInt64(), root.GetProperty("state").GetString() == "ok", root.GetProperty("log").GetString() ?? string.Empty);
    }

    /// <summary>The .zip of a folder's .cs files, with their paths relative to it.</summary>
    /// <param name="folder">The folder.</param>
    public static byte[] ZipSources(string folder)
    {
        var files = Directory.GetFiles(folder, "*.cs", SearchOption.AllDirectories).Order(StringComparer.Ordinal).ToArray();
        if (files.Length == 0)
        {
            throw new LadderInputException($"PATH: the folder {Engine.Messages.MessageText.Quote(folder)} holds no .cs file");
        }

        using var stream = new MemoryStream();
        using (var zip = new ZipArchive(stream, ZipArchiveMode.Create, leaveOpen: true))
        {
            foreach (string file in files)
            {
                string name = Path.GetRelativePath(folder, file).Replace(Path.DirectorySeparatorChar, '/');
                var entry = zip.CreateEntry(name, CompressionLevel.Optimal);
                using var output = entry.Open();
                using var input = File.OpenRead(file);
                input.CopyTo(output);
            }
        }

        return stream.ToArray();
    }

    /// <inheritdoc/>
    public void Dispose() => _http.Dispose();

    private async Task<JsonDocument> Send(Func<Task<HttpResponseMessage>> send, bool accept422 = false)
    {
        HttpResponseMessage response;
        try
        {
            response = await send();
        }
        catch (HttpRequestException e)
        {
            throw new LadderInputException($"--server: cannot reach {_http.BaseAddress} ({e.Message.ReplaceLineEndings(" ")})");
        }
        catch (TaskCanceledException)
        {
            throw new LadderInputException($"--server: {_http.BaseAddress} did not answer in time");
        }

        using (response)
        {
            string text = await response.Content.ReadAsStringAsync();
            JsonDocument document;
            try
            {
                document = JsonDocument.Parse(text);
            }
            catch (JsonException)
            {
                throw new LadderInputException($"--server: {_http.BaseAddress} answered HTTP {(int)response.StatusCode}, not the ladder's JSON");
            }

            if (response.IsSuccessStatusCode || (accept422 && (int)response.StatusCode == 422))
            {
                return document;
            }

            using (document)
            {
                string message = document.RootElement.ValueKind == JsonValueKind.Object && document.RootElement.TryGetProperty("error", out var e) ? e.GetString() ?? string.Empty : $"HTTP {(int)response.StatusCode}";
                throw new LadderInputException(message.StartsWith("ladder: ", StringComparison.Ordinal) ? "--" + message : message);
            }
        }
    }

    private static string Json(Action<Utf8JsonWriter> write)
    {
        using var stream = new MemoryStream();
        using (var w = new Utf8JsonWriter(stream, new JsonWriterOptions { Encoder = JavaScriptEncoder.UnsafeRelaxedJsonEscaping }))
        {
            write(w);
        }

        return Encoding.UTF8.GetString(stream.ToArray());
    }
}

/// <summary>A ladder of a service as <c>GET /api/ladders</c> describes it.</summary>
/// <param name="Id">Its id.</param>
/// <param name="Item">Its item (the slug).</param>
/// <param name="Cycles">Cycles per match.</param>
/// <param name="FirstSeed">The seed of match 0 (match N plays FirstSeed + N).</param>
/// <param name="Paused">Whether ranked play is paused.</param>
/// <param name="Teams">Teams in its standings.</param>
/// <param name="Matches">Matches in its standings.</param>
/// <param name="Leader">The team ranked first, or null before the first match.</param>
/// <param name="Final">Whether its final round has started.</param>
public sealed record LadderSummary(long Id, string Item, int Cycles, ulong FirstSeed, bool Paused, int Teams, int Matches, string? Leader, bool Final)
{
    internal static LadderSummary Of(JsonElement e) => new(
        e.GetProperty("id").GetInt64(),
        e.GetProperty("item").GetString()!,
        e.GetProperty("cycles").GetInt32(),
        ulong.Parse(e.GetProperty("firstSeed").GetString()!, System.Globalization.CultureInfo.InvariantCulture),
        e.GetProperty("paused").GetBoolean(),
        e.TryGetProperty("teams", out var teams) ? teams.GetInt32() : 0,
        e.TryGetProperty("matches", out var matches) ? matches.GetInt32() : 0,
        e.TryGetProperty("leader", out var leader) ? leader.GetString() : null,
        e.TryGetProperty("final", out _));
}
