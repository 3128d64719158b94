using System;
using System.Collections.Generic;
using System.Globalization;
using System.IO;
using System.Linq;
using System.Text.Json;
using System.Threading.Tasks;
using Microsoft.AspNetCore.Builder;
using Microsoft.AspNetCore.Http;
using Microsoft.AspNetCore.Routing;
using URWPGSim2D.Ladder.Play;
using URWPGSim2D.Ladder.Storage;
using URWPGSim2D.Tournament;

namespace URWPGSim2D.Ladder.Web;

/// <summary>
/// The JSON API beside every page. A request about one ladder names it with <c>?ladder=ID</c> (its
/// id, or its item when one ladder plays it), which may be left out when the service runs one
/// ladder. Reads are public but for a team's sources and logs (its own
/// token only); the organiser's actions need the organiser's token and a team's its own, each sent
/// as <c>Authorization: Bearer TOKEN</c> (never a cookie, so a page of another site cannot act for a
/// signed-in user). Bad input answers HTTP 400 with <c>{"error": "…"}</c>, one line naming the field.
/// </summary>
internal static class LadderApi
{
    public static void Map(IEndpointRouteBuilder app, LadderService service)
    {
        // The ladder a request names (?ladder=ID), or the only one.
        LadderCore Chosen(HttpRequest request) => service.Choose(request.Query["ladder"].ToString());

        app.MapGet("/api/ladder", (HttpRequest request) =>
        {
            var core = Chosen(request);
            return Json(JsonText.Of(w =>
            {
                w.WriteStartObject();
                WriteLadder(w, core);
                w.WriteNumber("workers", service.Workers);
                w.WriteNumber("submissionsPerDay", service.SubmissionsPerDay);
                w.WriteNumber("maxUploadBytes", service.Limits.MaxUploadBytes);
                w.WriteNumber("maxFiles", service.Limits.MaxFiles);
                w.WriteEndObject();
            }));
        });

        app.MapGet("/api/ladders", () => Json(JsonText.Of(w =>
        {
            w.WriteStartObject();
            w.WriteStartArray("ladders");
            foreach (var core in service.Cores())
            {
                var standings = core.Standings().Standings;
                w.WriteStartObject();
                WriteLadder(w, core);
                w.WriteNumber("teams", standings.Rows.Count);
                w.WriteNumber("matches", standings.Records.Count);
                if (standings.Rows.Where(r => r.Rank == 1).Select(r => r.Name).FirstOrDefault() is { } leader && standings.Records.Count > 0)
                {
                    w.WriteString("leader", leader);
                }

                w.WriteEndObject();
            }

            w.WriteEndArray();
            w.WriteStartArray("items");
            foreach (var item in LadderService.Items)
            {
                w.WriteStringValue(item.Slug);
            }

            w.WriteEndArray();
            w.WriteEndObject();
        })));

        app.MapPost("/api/ladders", async (HttpRequest request) =>
        {
            Admin(service, request);
            using var body = await Body(request);
            string item = Text(body.RootElement, "item", required: true)!;
            int? minutes = Whole(body.RootElement, "minutes", required: false);
            int? cycles = Whole(body.RootElement, "cycles", required: false);
            if (minutes is not null && cycles is not null)
            {
                throw new LadderInputException("minutes and cycles: give one of them, not both");
            }

            if (minutes is { } m && m is not (10 or 5 or 3 or 1))
            {
                throw new LadderInputException(string.Create(CultureInfo.InvariantCulture, $"minutes must be 10, 5, 3 or 1, got {m}"));
            }

            ulong firstSeed = 1;
            if (body.RootElement.TryGetProperty("firstSeed", out var seed) && seed.ValueKind != JsonValueKind.Null)
            {
                firstSeed = seed.ValueKind == JsonValueKind.Number && seed.TryGetUInt64(out ulong s) ? s
                    : throw new LadderInputException($"firstSeed must be a whole number from 0 to 18446744073709551615, got {seed.GetRawText()}");
            }

            var core = service.CreateLadder(item, cycles ?? (minutes ?? 10) * 600, firstSeed);
            return Json(JsonText.Of(w =>
            {
                w.WriteStartObject();
                WriteLadder(w, core);
                w.WriteEndObject();
            }), 201);
        });

        app.MapGet("/api/standings", (HttpRequest request) => Json(Chosen(request).Standings().Json));

        app.MapGet("/api/export/standings.json", (HttpRequest request) => Results.Text(Chosen(request).Standings().Json, "application/json", null, 200));

        app.MapGet("/api/export/results.jsonl", (HttpRequest request) => Results.Text(Export(Chosen(request)), "application/jsonl", null, 200));

        app.MapGet("/api/matches", (HttpRequest request) =>
        {
            var core = Chosen(request);
            string[] states = request.Query["state"].ToString() is { Length: > 0 } s ? s.Split(',') : [];
            foreach (string state in states)
            {
                if (state is not (MatchRow.Queued or MatchRow.Running or MatchRow.Done))
                {
                    throw new LadderInputException($"state must be queued, running or done (comma-separated), got {Engine.Messages.MessageText.Quote(state)}");
                }
            }

            int limit = request.Query["limit"].ToString() is { Length: > 0 } l ? Number("limit", l, 1, 10_000) : 200;
            string? team = request.Query["team"].ToString() is { Length: > 0 } t ? t : null;
            var teams = core.Store.Teams().ToDictionary(x => x.Id);
            var rows = core.Store.Matches(core.LadderId, states, team is null ? limit : 100_000);
            if (team is not null)
            {
                rows = [.. rows.Where(m => m.Teams.Any(id => teams[id].Name == team)).Take(limit)];
            }

            return Json(JsonText.Of(w =>
            {
                w.WriteStartObject();
                w.WriteStartArray("matches");
                foreach (var m in rows)
                {
                    WriteMatch(w, m, teams, core);
                }

                w.WriteEndArray();
                w.WriteEndObject();
            }));
        });

        app.MapGet("/api/matches/{id}", (string id) =>
        {
            var m = service.Store.Match(Id("match", id)) ?? throw new NotFound("match");
            var teams = service.Store.Teams().ToDictionary(x => x.Id);
            return Json(JsonText.Of(w => WriteMatch(w, m, teams, service.Core(m.LadderId))));
        });

        app.MapGet("/api/matches/{id}/replay", (string id) => Replay(service, id));
        app.MapGet("/matches/{id}/replay", (string id) => Replay(service, id));

        app.MapGet("/api/teams", (HttpRequest request) =>
        {
            var core = Chosen(request);
            var games = core.Store.Games(core.LadderId);
            var playing = core.Playing();
            return Json(JsonText.Of(w =>
            {
                w.WriteStartObject();
                w.WriteStartArray("teams");
                foreach (var t in core.Store.Teams().Where(t => t.House is null || t.LadderId == core.LadderId))
                {
                    w.WriteStartObject();
                    w.WriteString("name", t.Name);
                    if (t.House is { } house)
                    {
                        w.WriteString("house", house);
                    }

                    if (playing.TryGetValue(t.Id, out var p) && p.Submission != 0)
                    {
                        w.WriteNumber("submission", p.Submission);
                    }

                    w.WriteNumber("games", games.TryGetValue(t.Id, out int g) ? g : 0);
                    w.WriteEndObject();
                }

                w.WriteEndArray();
                w.WriteEndObject();
            }));
        });

        app.MapGet("/api/teams/{name}", (string name, HttpRequest request) =>
        {
            var team = service.Store.TeamByName(name) ?? throw new NotFound("team");
            var me = service.TeamOf(Bearer(request));
            bool own = me is not null && me.Id == team.Id;
            return Json(JsonText.Of(w =>
            {
                w.WriteStartObject();
                w.WriteString("name", team.Name);
                if (team.House is { } house)
                {
                    w.WriteString("house", house);
                    w.WriteNumber("ladder", team.LadderId);
                }

                w.WriteBoolean("signedIn", own);
                if (Faults(service, team) is { } faults)
                {
                    w.WriteStartObject("faults");
                    w.WriteNumber("exceptions", faults.Exceptions);
                    w.WriteNumber("timeouts", faults.Timeouts);
                    w.WriteNumber("badAnswers", faults.BadAnswers);
                    w.WriteNumber("hostEnds", faults.HostEnds);
                    w.WriteNumber("matches", faults.Matches);
                    w.WriteString("counts", faults.Counts());
                    w.WriteStartObject("first");
                    w.WriteNumber("match", faults.FirstMatch);
                    if (faults.FirstCycle is { } cycle)
                    {
                        w.WriteNumber("cycle", cycle);
                    }

                    w.WriteString("text", faults.FirstText);
                    w.WriteEndObject();
                    w.WriteEndObject();
                }

                w.WriteStartArray("submissions");
                foreach (var s in service.Store.Submissions(team.Id))
                {
                    w.WriteStartObject();
                    w.WriteNumber("id", s.Id);
                    w.WriteNumber("ladder", s.LadderId);
                    w.WriteString("created", s.Created);
                    w.WriteString("state", s.State);
                    if (own)
                    {
                        w.WriteString("log", s.Log); // a team's compile log is its own
                    }

                    w.WriteEndObject();
                }

                w.WriteEndArray();
                w.WriteEndObject();
            }));
        });

        app.MapGet("/api/teams/{name}/matches/{id}/log", (string name, string id, HttpRequest request) =>
        {
            var team = service.Store.TeamByName(name) ?? throw new NotFound("team");
            var me = service.TeamOf(Bearer(request)) ?? throw new Unauthorised("authorization: a team's strategy log needs its token (Authorization: Bearer TOKEN)");
            if (me.Id != team.Id)
            {
                return Problem(403, "authorization: a team's strategy log is its own");
            }

            var m = service.Store.Match(Id("match", id)) ?? throw new NotFound("match");
            int[] order = m.Id % 2 == 0 ? [0, 1] : [1, 0];
            int side = Array.IndexOf(order.Select(k => m.Teams[k]).ToArray(), team.Id);
            if (side < 0)
            {
                throw new NotFound("match of this team");
            }

            var outputs = MatchOutputs.Read(service.Core(m.LadderId).Files.Read(m.Id, LadderFiles.Outputs)) ?? throw new NotFound("log (the match is not played yet)");
            return Json(JsonText.Of(w =>
            {
                w.WriteStartObject();
                w.WriteNumber("match", m.Id);
                w.WriteNumber("side", side);
                if (outputs[side].SlowestMs is { } ms)
                {
                    w.WriteNumber("slowestMs", ms);
                }

                w.WriteString("log", outputs[side].Log);
                w.WriteEndObject();
            }));
        });

        app.MapGet("/api/me", (HttpRequest request) =>
        {
            string? token = Bearer(request);
            bool admin = service.IsAdmin(token);
            var team = admin ? null : service.TeamOf(token);
            if (!admin && team is null)
            {
                return Problem(401, "authorization: no valid token (send Authorization: Bearer TOKEN)");
            }

            return Json(JsonText.Of(w =>
            {
                w.WriteStartObject();
                w.WriteString("role", admin ? "organiser" : "team");
                if (team is not null)
                {
                    w.WriteString("name", team.Name);
                }

                w.WriteEndObject();
            }));
        });

        app.MapPost("/api/teams", async (HttpRequest request) =>
        {
            Admin(service, request);
            using var body = await Body(request);
            string name = Text(body.RootElement, "name", required: true)!;
            string? strategy = Text(body.RootElement, "strategy", required: false);
            var (team, token) = service.AddTeam(name, strategy, request.Query["ladder"].ToString());
            return Json(JsonText.Of(w =>
            {
                w.WriteStartObject();
                w.WriteString("name", team.Name);
                if (team.House is { } house)
                {
                    w.WriteString("house", house);
                    w.WriteNumber("ladder", team.LadderId);
                }

                w.WriteString("token", token);
                w.WriteEndObject();
            }), 201);
        });

        app.MapPost("/api/signin", async (HttpRequest request) =>
        {
            using var body = await Body(request);
            string name = Text(body.RootElement, "name", required: true)!;
            string password = Text(body.RootElement, "password", required: true)!;
            var team = service.SignIn(name, password);
            if (team is null)
            {
                return Problem(401, "signin: wrong team name or password");
            }

            string token = service.NewSession(team);
            return Json(JsonText.Of(w =>
            {
                w.WriteStartObject();
                w.WriteString("name", team.Name);
                w.WriteString("token", token);
                w.WriteEndObject();
            }));
        });

        app.MapPost("/api/password", async (HttpRequest request) =>
        {
            var team = Team(service, request);
            using var body = await Body(request);
            service.SetPassword(team, Text(body.RootElement, "password", required: true)!);
            return Json("{\"ok\": true}");
        });

        app.MapPost("/api/submissions", async (HttpRequest request) =>
        {
            var team = Team(service, request);
            var core = Chosen(request);
            if (!request.HasFormContentType)
            {
                throw new LadderInputException("upload: send the files as multipart/form-data (field \"file\")");
            }

            var form = await request.ReadFormAsync();
            var files = new List<UploadedFile>();
            foreach (var f in form.Files)
            {
                if (files.Count >= service.Limits.MaxFiles)
                {
                    throw new LadderInputException(string.Create(CultureInfo.InvariantCulture, $"upload: more than the limit of {service.Limits.MaxFiles} files"));
                }

                using var stream = new MemoryStream();
                await f.CopyToAsync(stream);
                files.Add(new UploadedFile(f.FileName, stream.ToArray()));
            }

            var s = await Task.Run(() => core.Submit(team, files));
            return Json(JsonText.Of(w =>
            {
                w.WriteStartObject();
                w.WriteNumber("id", s.Id);
                w.WriteNumber("ladder", s.LadderId);
                w.WriteString("kind", s.Kind);
                w.WriteString("state", s.State);
                w.WriteString("log", s.Log);
                w.WriteEndObject();
            }), s.State == SubmissionRow.Ok ? 201 : 422);
        });

        app.MapPost("/api/ladder/pause", (HttpRequest request) =>
        {
            Admin(service, request);
            Chosen(request).SetPaused(true);
            return Json("{\"paused\": true}");
        });

        app.MapPost("/api/ladder/resume", (HttpRequest request) =>
        {
            Admin(service, request);
            Chosen(request).SetPaused(false);
            return Json("{\"paused\": false}");
        });

        app.MapPost("/api/settings", async (HttpRequest request) =>
        {
            Admin(service, request);
            using var body = await Body(request);
            if (body.RootElement.TryGetProperty("submissionsPerDay", out var limit))
            {
                service.SetSubmissionsPerDay(limit.ValueKind == JsonValueKind.Number && limit.TryGetInt32(out int n) ? n : throw new LadderInputException($"submissionsPerDay must be a whole number, got {limit.GetRawText()}"));
            }

            return Json("{\"ok\": true}");
        });

        app.MapPost("/api/final", async (HttpRequest request) =>
        {
            Admin(service, request);
            var core = Chosen(request);
            using var body = await Body(request);
            int top = Whole(body.RootElement, "top", required: true)!.Value;
            int rounds = Whole(body.RootElement, "rounds", required: false) ?? 2;
            var final = await Task.Run(() => core.StartFinal(top, rounds));
            return Json(JsonText.Of(w =>
            {
                w.WriteStartObject();
                WriteFinal(w, final, core);
                w.WriteEndObject();
            }), 201);
        });

        app.MapPost("/api/matches/{id}/requeue", (string id, HttpRequest request) =>
        {
            Admin(service, request);
            long match = Id("match", id);
            (service.Store.Match(match) is { } m ? service.Core(m.LadderId) : service.Core(service.Served)).Requeue(match);
            return Json("{\"requeued\": true}");
        });
    }

    // results.jsonl: a tournament result file (its header, then one record per finished match), which `tournament` and `merge` read.
    private static string Export(LadderCore core)
    {
        var (standings, _) = core.Standings();
        string path = Path.Combine(Path.GetTempPath(), "urwpgsim2d-ladder-" + Guid.NewGuid().ToString("N") + ".jsonl");
        try
        {
            TournamentFile.Write(path, standings.Header, standings.Records);
            return File.ReadAllText(path);
        }
        finally
        {
            File.Delete(path);
        }
    }

    // A team's runtime faults over its finished matches of every ladder (the tournament's sum, per match id), or null when it had none.
    private static EntrantFaults? Faults(LadderService service, TeamRow team)
    {
        EntrantFaults? sum = null;
        foreach (var m in service.Cores().SelectMany(c => c.Store.Matches(c.LadderId, [MatchRow.Done], 100_000)).Where(m => m.Teams.Contains(team.Id)).OrderBy(m => m.Id))
        {
            var r = TournamentFile.ParseRecord(m.Record!);
            int side = r.Entrants.ToList().IndexOf(team.Name);
            bool newMatch = true;
            foreach (var f in r.Result?.Faults ?? [])
            {
                if (f.Team == side)
                {
                    sum = EntrantFaults.Add(sum, checked((int)m.Id), f, newMatch);
                    newMatch = false;
                }
            }
        }

        return sum;
    }

    // "final": {"teams": [names], "rounds", "played", "matches"}.
    private static void WriteFinal(System.Text.Json.Utf8JsonWriter w, FinalRound final, LadderCore core)
    {
        w.WriteStartObject("final");
        w.WriteStartArray("teams");
        foreach (var t in core.Store.Teams().Where(t => final.Teams.ContainsKey(t.Id)))
        {
            w.WriteStringValue(t.Name);
        }

        w.WriteEndArray();
        w.WriteNumber("rounds", final.Rounds);
        w.WriteNumber("played", final.Played);
        w.WriteNumber("matches", final.Matches);
        w.WriteEndObject();
    }

    // A ladder's id, item, match length, first seed, whether paused, and once started its final round.
    private static void WriteLadder(System.Text.Json.Utf8JsonWriter w, LadderCore core)
    {
        var l = core.Ladder;
        w.WriteNumber("id", l.Id);
        w.WriteString("item", l.Item);
        w.WriteNumber("cycles", l.Cycles);
        w.WriteString("firstSeed", l.FirstSeed.ToString(CultureInfo.InvariantCulture));
        w.WriteBoolean("paused", l.Paused);
        if (core.Final() is { } final)
        {
            WriteFinal(w, final, core);
        }
    }

    private static IResult Replay(LadderService service, string id)
    {
        long match = Id("match", id);
        return service.Core(service.Served).Files.Read(match, LadderFiles.Replay) is { } page ? Results.Bytes(page, "text/html; charset=utf-8") : throw new NotFound("replay");
    }

    private static void WriteMatch(System.Text.Json.Utf8JsonWriter w, MatchRow m, Dictionary<long, TeamRow> teams, LadderCore core)
    {
        w.WriteStartObject();
        w.WriteNumber("id", m.Id);
        w.WriteNumber("ladder", m.LadderId);
        w.WriteString("seed", m.Seed.ToString(CultureInfo.InvariantCulture));
        w.WriteString("state", m.State);
        if (m.Final)
        {
            w.WriteBoolean("final", true);
        }

        // Sides as played: even ids keep the queued order, odd ids swap it.
        int[] order = m.Id % 2 == 0 ? [0, 1] : [1, 0];
        w.WriteStartArray("teams");
        foreach (int k in order)
        {
            w.WriteStringValue(teams[m.Teams[k]].Name);
        }

        w.WriteEndArray();
        w.WriteStartArray("submissions");
        foreach (int k in order)
        {
            if (m.Submissions[k] == 0)
            {
                w.WriteNullValue();
            }
            else
            {
                w.WriteNumberValue(m.Submissions[k]);
            }
        }

        w.WriteEndArray();
        w.WriteString("created", m.Created);
        if (m.Started is { } started)
        {
            w.WriteString("started", started);
        }

        if (m.Finished is { } finished)
        {
            w.WriteString("finished", finished);
        }

        if (m.Record is { } line)
        {
            var r = TournamentFile.ParseRecord(line);
            if (r.Result is { } result)
            {
                w.WriteStartArray("score");
                foreach (int s in result.Scores ?? [result.Goals0, result.Goals1])
                {
                    w.WriteNumberValue(s);
                }

                w.WriteEndArray();
                w.WriteNumber("winner", result.Winner);
                w.WriteNumber("faults", result.StrategyFaults);
                w.WriteStartArray("sideFaults");
                for (int side = 0; side < r.Entrants.Count; side++)
                {
                    var f = result.Faults?.Where(x => x.Team == side).ToList() ?? [];
                    if (f.Count == 0)
                    {
                        w.WriteNullValue();
                        continue;
                    }

                    w.WriteStartObject();
                    w.WriteNumber("exceptions", f.Sum(x => x.Exceptions));
                    w.WriteNumber("timeouts", f.Sum(x => x.Timeouts));
                    w.WriteNumber("badAnswers", f.Sum(x => x.BadAnswers));
                    w.WriteNumber("hostEnds", f.Sum(x => x.Crashes));
                    w.WriteString("first", f[0].First);
                    w.WriteEndObject();
                }

                w.WriteEndArray();
            }
            else
            {
                TournamentFile.WriteForfeits(w, r);
            }

            if (MatchOutputs.Read(core.Files.Read(m.Id, LadderFiles.Outputs)) is { } outputs)
            {
                w.WriteStartArray("slowestMs");
                foreach (var side in outputs)
                {
                    if (side.SlowestMs is { } ms)
                    {
                        w.WriteNumberValue(ms);
                    }
                    else
                    {
                        w.WriteNullValue();
                    }
                }

                w.WriteEndArray();
            }

            if (core.Files.Has(m.Id, LadderFiles.Replay))
            {
                w.WriteString("replay", string.Create(CultureInfo.InvariantCulture, $"/matches/{m.Id}/replay"));
            }
        }

        w.WriteEndObject();
    }

    /// <summary>The bearer token of a request, or null.</summary>
    public static string? Bearer(HttpRequest request)
    {
        string header = request.Headers.Authorization.ToString();
        return header.StartsWith("Bearer ", StringComparison.Ordinal) ? header["Bearer ".Length..].Trim() : null;
    }

    private static void Admin(LadderService service, HttpRequest request)
    {
        if (!service.IsAdmin(Bearer(request)))
        {
            throw new Unauthorised("authorization: this needs the organiser's token (Authorization: Bearer TOKEN)");
        }
    }

    private static TeamRow Team(LadderService service, HttpRequest request) =>
        service.TeamOf(Bearer(request)) ?? throw new Unauthorised("authorization: this needs a team's token (Authorization: Bearer TOKEN)");

    private static async Task<JsonDocument> Body(HttpRequest request)
    {
        try
        {
            var document = await JsonDocument.ParseAsync(request.Body);
            return document.RootElement.ValueKind == JsonValueKind.Object ? document : throw new LadderInputException("body must be a JSON object");
        }
        catch (JsonException e)
        {
            throw new LadderInputException($"body is not JSON: {e.Message.ReplaceLineEndings(" ")}");
        }
    }

    private static string? Text(JsonElement body, string name, bool required)
    {
        if (!body.TryGetProperty(name, out var value) || value.ValueKind == JsonValueKind.Null)
        {
            return required ? throw new LadderInputException($"{name} is required") : null;
        }

        return value.ValueKind == JsonValueKind.String ? value.GetString()! : throw new LadderInputException($"{name} must be a string, got {value.GetRawText()}");
    }

    private static int? Whole(JsonElement body, string name, bool required)
    {
        if (!body.TryGetProperty(name, out var value) || value.ValueKind == JsonValueKind.Null)
        {
            return required ? throw new LadderInputException($"{name} is required") : null;
        }

        return value.ValueKind == JsonValueKind.Number && value.TryGetInt32(out int n) ? n : throw new LadderInputException($"{name} must be a whole number, got {value.GetRawText()}");
    }

    private static long Id(string field, string text) =>
        long.TryParse(text, NumberStyles.None, CultureInfo.InvariantCulture, out long id) && id > 0 ? id : throw new LadderInputException($"{field} must be a match id (a whole number ≥ 1), got {Engine.Messages.MessageText.Quote(text)}");

    private static int Number(string field, string text, int low, int high) =>
        int.TryParse(text, NumberStyles.None, CultureInfo.InvariantCulture, out int n) && n >= low && n <= high ? n
        : throw new LadderInputException(string.Create(CultureInfo.InvariantCulture, $"{field} must be a whole number from {low} to {high}, got {Engine.Messages.MessageText.Quote(text)}"));

    private static IResult Json(string json, int status = 200) => Results.Text(json, "application/json; charset=utf-8", null, status);

    /// <summary>An error answer: <c>{"error": message}</c> with the status.</summary>
    public static IResult Problem(int status, string message) => Json(JsonText.Error(message), status);

    /// <summary>No such thing: 404.</summary>
    internal sealed class NotFound(string what) : Exception($"{what}: not found");

    /// <summary>No valid token for the action: 401.</summary>
    internal sealed class Unauthorised(string message) : Exception(message);
}
