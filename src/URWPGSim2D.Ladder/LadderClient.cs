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
/// The ladder's API from a program: what <c>urwpgsim2d ladder team add</c> and <c>ladder submit</c>
/// send. A refusal of the service (its one-line JSON error) or an unreachable service throws
/// <see cref="LadderInputException"/> with that line.
/// </summary>
public sealed class LadderClient : IDisposable
{
    private readonly HttpClient _http;

    /// <summary>A client of the service at <paramref name="server"/> (e.g. <c>http://127.0.0.1:5080/</c>).</summary>
    /// <param name="server">The service's address.</param>
    /// <param name="token">The organiser's or a team's token, sent as <c>Authorization: Bearer</c>.</param>
    public LadderClient(string server, string token)
    {
        ArgumentNullException.ThrowIfNull(server);
        ArgumentNullException.ThrowIfNull(token);
        if (!Uri.TryCreate(server.EndsWith('/') ? server : server + "/", UriKind.Absolute, out var uri) || uri.Scheme is not ("http" or "https"))
        {
            throw new LadderInputException($"--server must be an http:// or https:// address, got {Engine.Messages.MessageText.Quote(server)}");
        }

        _http = new HttpClient { BaseAddress = uri, Timeout = TimeSpan.FromMinutes(10) };
        _http.DefaultRequestHeaders.Authorization = new AuthenticationHeaderValue("Bearer", token);
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
        using var answer = await Send(() => _http.PostAsync("api/teams", new StringContent(body, Encoding.UTF8, "application/json")));
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
        using var answer = await Send(() => _http.PostAsync("api/final", new StringContent(body, Encoding.UTF8, "application/json")));
        var final = answer.RootElement.GetProperty("final");
        return ([.. final.GetProperty("teams").EnumerateArray().Select(t => t.GetString()!)], final.GetProperty("matches").GetInt32());
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

        using var answer = await Send(() => _http.PostAsync("api/submissions", form), accept422: true);
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
                throw new LadderInputException(message);
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
