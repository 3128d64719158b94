using URWPGSim2D.Hosting;

namespace URWPGSim2D.Ladder.Tests;

/// <summary>
/// Teams whose strategies attack the sandbox: one reads files outside it (the ladder's database, a
/// secret beside it), starts processes without end and allocates without bound; one spins forever.
/// The ladder keeps running: every match completes with a result, the faults are the attackers'
/// (their opponents have none), nothing outside leaks, and the other teams' matches go on.
/// </summary>
public sealed class HostileLadderTests : IAsyncLifetime
{
    private const string Secret = "LADDER-SECRET-4f1c";

    private LadderHost _host = null!;

    public async Task InitializeAsync() =>
        _host = await LadderHost.StartAsync(workers: 1, hostSettings: new HostSettings(Sandbox: SandboxMode.Required, MemoryMb: 128, Processes: 64));

    public async Task DisposeAsync() => await _host.DisposeAsync();

    private static string Strategy(string name, string body) => "using System; using System.Collections.Generic; using System.Diagnostics; using System.IO; using URWPGSim2D.Strategies;\n" + $$"""
        public sealed class {{name}} : IStrategy
        {
            private static readonly List<byte[]> Hoard = new List<byte[]>();

            public string TeamName => "{{name}}";

            public void Decide(MatchSnapshot snapshot, ReadOnlySpan<int> fish, Span<Decision> decisions)
            {
                for (int k = 0; k < decisions.Length; k++)
                {
                    decisions[k] = new Decision(10, 7);
                }

                {{body}}
            }
        }
        """;

    private async Task<string> Team(string name, string? house = null, string? source = null)
    {
        string json = house is null ? $"{{\"name\": \"{name}\"}}" : $"{{\"name\": \"{name}\", \"strategy\": \"{house}\"}}";
        string token = (await _host.Send(HttpMethod.Post, "/api/teams", LadderHost.AdminToken, json)).Body.GetProperty("token").GetString()!;
        if (source is not null)
        {
            using var form = new MultipartFormDataContent { { new ByteArrayContent(Encoding.UTF8.GetBytes(source)), "file", name + ".cs" } };
            var submitted = await _host.Send(HttpMethod.Post, "/api/submissions", token, content: form);
            Assert.True(submitted.Status == 201, submitted.Body.GetRawText());
        }

        return token;
    }

    [Fact]
    public async Task AttacksOnTheSandboxAreTheAttackersFaultsAndTheLadderPlaysOn()
    {
        string secret = Path.Combine(_host.Folder, "secret.txt");
        File.WriteAllText(secret, Secret);
        string database = Path.Combine(_host.Folder, "ladder.db");
        string intruder = await Team("intruder", source: Strategy("Intruder", $$"""
            if (snapshot.Cycle == 1)
            {
                foreach (string path in new[] { @"{{secret}}", @"{{database}}", "/etc/shadow" })
                {
                    try { Console.WriteLine("read " + path + ": " + File.ReadAllText(path)); }
                    catch (Exception e) { Console.WriteLine("read refused: " + e.GetType().Name); }
                }

                try { for (int i = 0; i < 5000; i++) Process.Start(new ProcessStartInfo("/bin/sleep", "1000") { UseShellExecute = false }); }
                catch (Exception e) { Console.WriteLine("fork refused: " + e.GetType().Name); }
            }

            if (snapshot.Cycle >= 2)
            {
                while (true) Hoard.Add(new byte[1 << 20]);
            }
            """));
        await Team("spinner", source: Strategy("Spinner", "if (snapshot.Cycle >= 1) { while (true) { } }"));
        await Team("champion", house: "demo");
        await Team("sleeper", house: "idle");

        string[] teams = ["intruder", "spinner", "champion", "sleeper"];
        await LadderHost.Until(async () =>
        {
            foreach (string team in teams)
            {
                if ((await _host.Get($"/api/matches?team={team}&state=done")).Body.GetProperty("matches").GetArrayLength() < 2)
                {
                    return false;
                }
            }

            return true;
        }, "every team played two matches", minutes: 15);
        await _host.Send(HttpMethod.Post, "/api/ladder/pause", LadderHost.AdminToken);
        await LadderHost.Until(async () => (await _host.Get("/api/matches?state=running")).Body.GetProperty("matches").GetArrayLength() == 0, "the running match finished");

        // Every match completed with a result; each attacker's side has faults, each house side none.
        var done = (await _host.Get("/api/matches?state=done&limit=1000")).Body.GetProperty("matches").EnumerateArray().ToList();
        foreach (var m in done)
        {
            Assert.True(m.TryGetProperty("score", out _), "a match without a result: " + m.GetRawText());
            var names = m.GetProperty("teams").EnumerateArray().Select(t => t.GetString()!).ToList();
            for (int side = 0; side < 2; side++)
            {
                bool hostile = names[side] is "intruder" or "spinner";
                Assert.True(hostile == (m.GetProperty("sideFaults")[side].ValueKind == JsonValueKind.Object), $"side {side} of {m.GetRawText()}");
            }
        }

        // The house teams' matches went on: they played each other or the attackers, and carry no fault in the standings.
        var standings = (await _host.Get("/api/standings")).Body.GetProperty("entrants").EnumerateArray().ToDictionary(e => e.GetProperty("name").GetString()!);
        Assert.False(standings["champion"].TryGetProperty("faults", out _));
        Assert.False(standings["sleeper"].TryGetProperty("faults", out _));
        Assert.True(standings["intruder"].TryGetProperty("faults", out _));
        Assert.True(standings["spinner"].TryGetProperty("faults", out _));

        // Nothing outside the sandbox was read: the intruder's own log says each read was refused.
        var first = done.Where(m => m.GetProperty("teams").EnumerateArray().Any(t => t.GetString() == "intruder")).OrderBy(m => m.GetProperty("id").GetInt64()).First();
        string log = (await _host.Get($"/api/teams/intruder/matches/{first.GetProperty("id").GetInt64()}/log", intruder)).Body.GetProperty("log").GetString()!;
        Assert.Equal(3, log.Split('\n').Count(l => l.Contains("read refused: ", StringComparison.Ordinal)));
        Assert.DoesNotContain(Secret, log, StringComparison.Ordinal);
        Assert.DoesNotContain("SQLite format", log, StringComparison.Ordinal);
        Assert.DoesNotContain(Secret, await _host.Http.GetStringAsync("/api/export/results.jsonl"), StringComparison.Ordinal);

        // The service answers as before.
        Assert.Equal(200, (await _host.Get("/api/ladder")).Status);
    }
}
