using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using System.Net;
using System.Reflection;
using System.Threading.Tasks;
using Microsoft.AspNetCore.Builder;
using Microsoft.AspNetCore.Hosting;
using Microsoft.AspNetCore.Hosting.Server;
using Microsoft.AspNetCore.Hosting.Server.Features;
using Microsoft.AspNetCore.Http;
using Microsoft.AspNetCore.Http.Features;
using Microsoft.Extensions.DependencyInjection;
using Microsoft.Extensions.Hosting;
using Microsoft.Extensions.Logging;
using URWPGSim2D.Ladder.Storage;

namespace URWPGSim2D.Ladder.Web;

/// <summary>
/// The ladder service: the pages and JSON API (ASP.NET Core, Kestrel) over the ladder's database,
/// and the workers that play ranked matches without end. Listens on loopback unless a host is
/// given. <see cref="StartAsync"/> migrates the database, checks again what a stopped service was
/// checking, puts what it was playing back in the queue and starts the workers.
/// </summary>
public sealed class LadderServer : IAsyncDisposable
{
    private readonly WebApplication _app;
    private readonly LadderService _service;
    private readonly LadderWorkers? _workers;
    private readonly LadderJobs? _jobs;
    private readonly LadderMatchmaker? _matchmaker;

    private LadderServer(WebApplication app, LadderService service, LadderWorkers? workers, LadderJobs? jobs, LadderMatchmaker? matchmaker, string url)
    {
        _app = app;
        _service = service;
        _workers = workers;
        _jobs = jobs;
        _matchmaker = matchmaker;
        Url = url;
    }


    /// <summary>The address the service answers at, e.g. <c>http://127.0.0.1:5080/</c>.</summary>
    public string Url { get; }

    /// <summary>The organiser's token made on this first start (to print once), or null.</summary>
    public string? NewAdminToken => _service.NewAdminToken;

    /// <summary>The item (its slug) of the ladder created or reopened on start: the one <see cref="LadderSettings.Item"/> names, else the newest.</summary>
    public string Item => _service.Core(_service.Served).Item.Slug;

    /// <summary>The service's ladders: each one's id and item (its slug), by id.</summary>
    public IReadOnlyList<(long Id, string Item)> Ladders => [.. _service.Cores().Select(c => (c.LadderId, c.Item.Slug))];

    /// <summary>Starts the service.</summary>
    /// <param name="settings">Its settings.</param>
    /// <param name="report">Told a line for each problem a worker meets.</param>
    /// <exception cref="LadderInputException">A setting is wrong (the message names it).</exception>
    public static async Task<LadderServer> StartAsync(LadderSettings settings, Action<string> report)
    {
        ArgumentNullException.ThrowIfNull(settings);
        ArgumentNullException.ThrowIfNull(report);
        if (!IPAddress.TryParse(settings.Host, out var address) && settings.Host != "localhost")
        {
            throw new LadderInputException($"--host must be an IP address or localhost, got {Engine.Messages.MessageText.Quote(settings.Host)}");
        }

        if (settings.Takeover is not null && settings.Database is null)
        {
            throw new LadderInputException("--takeover: only with --database (PostgreSQL), where worker processes take matches over");
        }

        Directory.CreateDirectory(settings.DataDir);
        var store = LadderDatabase.Open(settings);
        LadderService service;
        try
        {
            service = new LadderService(store, settings);
        }
        catch
        {
            store.Dispose();
            throw;
        }

        service.Core(service.Served).Files.Import(); // a data folder of an older version: its files into the database (every ladder's)
        service.RecheckInterrupted();
        if (settings.Database is null)
        {
            // SQLite: this process alone plays, so what was running when it stopped is played again.
            store.RequeueRunning();
        }

        var builder = WebApplication.CreateSlimBuilder();
        builder.Logging.ClearProviders();
        builder.WebHost.ConfigureKestrel(k =>
        {
            k.Limits.MaxRequestBodySize = settings.Limits.MaxUploadBytes + (256 * 1024);
            if (address is null)
            {
                k.ListenLocalhost(settings.Port);
            }
            else
            {
                k.Listen(address, settings.Port);
            }
        });
        builder.Services.Configure<FormOptions>(o =>
        {
            o.MultipartBodyLengthLimit = settings.Limits.MaxUploadBytes + (64 * 1024);
            o.ValueCountLimit = settings.Limits.MaxFiles + 16;
        });
        builder.Services.AddRoutingCore();
        var app = builder.Build();
        app.Use(Guard);
        app.UseRouting();
        LadderApi.Map(app, service);
        LadderPages.Map(app);
        await app.StartAsync();
        string url = app.Services.GetRequiredService<IServer>().Features.Get<IServerAddressesFeature>()!.Addresses.First();
        if (settings.Database is { } database)
        {
            // PostgreSQL: matches are Hangfire jobs, played by this process's server (--workers) and by every worker process.
            var jobs = new LadderJobs(database, LadderJobs.Takeover(store, settings.Takeover));
            if (settings.Workers > 0)
            {
                // This process's jobs play with the service's own cores (their warm hosts), every ladder's.
                jobs.Serve(settings.Workers, new MatchJob(store, service.Core, (_, _) => { }));
            }

            var matchmaker = new LadderMatchmaker(service, jobs, report);
            matchmaker.Start();
            return new LadderServer(app, service, null, jobs, matchmaker, url.TrimEnd('/') + "/");
        }

        var workers = settings.Workers > 0 ? new LadderWorkers(service, settings.Workers, report) : null;
        workers?.Start();
        return new LadderServer(app, service, workers, null, null, url.TrimEnd('/') + "/");
    }

    /// <summary>Waits until the service is stopped (Ctrl+C, SIGTERM).</summary>
    public Task WaitForShutdownAsync() => _app.WaitForShutdownAsync();

    /// <summary>Stops the workers (the matches they play finish) and the web server.</summary>
    public async ValueTask DisposeAsync()
    {
        _workers?.Dispose();
        _matchmaker?.Dispose();
        _jobs?.Dispose();
        await _app.StopAsync();
        await _app.DisposeAsync();
        _service.Dispose();
    }

    // Every request: a cross-site request that would change something is refused (its Origin is not this
    // service), and every failure answers one JSON line: 400 bad input, 401 no token, 404 not found, 413 too large.
    private static async Task Guard(HttpContext context, RequestDelegate next)
    {
        var request = context.Request;
        if (!HttpMethods.IsGet(request.Method) && !HttpMethods.IsHead(request.Method)
            && request.Headers.Origin.ToString() is { Length: > 0 } origin
            && !(Uri.TryCreate(origin, UriKind.Absolute, out var o) && string.Equals(o.Authority, request.Host.Value, StringComparison.OrdinalIgnoreCase)))
        {
            await Answer(context, 403, $"origin: a request from {origin} may not change this ladder");
            return;
        }

        try
        {
            await next(context);
        }
        catch (LadderInputException e)
        {
            await Answer(context, 400, e.Message);
        }
        catch (LadderApi.Unauthorised e)
        {
            await Answer(context, 401, e.Message);
        }
        catch (LadderApi.NotFound e)
        {
            await Answer(context, 404, e.Message);
        }
        catch (BadHttpRequestException e) when (e.StatusCode == StatusCodes.Status413PayloadTooLarge)
        {
            await Answer(context, 413, "upload: larger than the limit of the upload size");
        }
        catch (InvalidDataException e)
        {
            await Answer(context, 413, "upload: " + e.Message.ReplaceLineEndings(" "));
        }
        catch (BadHttpRequestException e)
        {
            await Answer(context, 400, "request: " + e.Message.ReplaceLineEndings(" "));
        }
        catch (Exception e) when (e is not OutOfMemoryException)
        {
            await Answer(context, 500, $"internal error: {e.GetType().Name}: {e.Message.ReplaceLineEndings(" ")}");
        }
    }

    private static async Task Answer(HttpContext context, int status, string message)
    {
        if (context.Response.HasStarted)
        {
            return;
        }

        context.Response.Clear();
        context.Response.StatusCode = status;
        context.Response.ContentType = "application/json; charset=utf-8";
        await context.Response.WriteAsync(JsonText.Error(message));
    }
}
