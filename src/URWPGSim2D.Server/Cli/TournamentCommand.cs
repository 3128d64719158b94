using System.Diagnostics;
using URWPGSim2D.Tournament.Batch;
using URWPGSim2D.Tournament.Batch.Slurm;
using URWPGSim2D.Tournament;

namespace URWPGSim2D.Server.Cli;

/// <summary>
/// <c>tournament</c>: plays every entrant against every other (or alone, for a one-team item) on a
/// deterministic schedule over N seeds, on every core or as a Slurm job array, resuming what its
/// folder already holds, and writes the results, the standings with their intervals and a report
/// page. See docs/tournament.md.
/// </summary>
internal sealed class TournamentCommand : ICliCommand
{
    /// <inheritdoc/>
    public string Name => "tournament";

    /// <inheritdoc/>
    public string Synopsis => TournamentOptions.Synopsis;

    /// <inheritdoc/>
    public string Summary => "Rank strategies: every entrant against every other over N seeds, ratings with 95 % intervals, report page.";

    /// <inheritdoc/>
    public Command Syntax => TournamentSyntax.Command;

    /// <inheritdoc/>
    public int Run(IReadOnlyList<CommandLineWord> words, CliConsole console)
    {
        var o = TournamentOptions.Parse(words);
        if (o.Help)
        {
            console.Out.Write(HelpText());
            return ExitCodes.Success;
        }

        if (o.Check)
        {
            return CheckEntrants(o, console);
        }

        TournamentSchedule schedule;
        try
        {
            schedule = new TournamentSchedule(o.Item.TeamCount, o.Entrants.Count, o.Seeds, o.FirstSeed);
        }
        catch (ArgumentException e)
        {
            return Refuse(console, $"--seeds {o.Seeds} --seed {o.FirstSeed}: {e.Message.Split(" (Parameter", 2)[0]}");
        }

        var whole = new TournamentHeader(o.Item.Slug, o.Entrants, o.Seeds, o.FirstSeed, o.Cycles, o.StrategyTimeoutMs, o.Cup?.PlannedMatches ?? schedule.Matches.Count);
        string folder;
        try
        {
            folder = Path.TrimEndingDirectorySeparator(Path.GetFullPath(o.Out));
        }
        catch (Exception e) when (e is ArgumentException or NotSupportedException or PathTooLongException)
        {
            return Refuse(console, $"--out: not a usable path ({e.Message})");
        }

        if (File.Exists(folder))
        {
            return Refuse(console, $"--out: {o.Out} is a file, not a folder");
        }

        if (o.Slurm is not null)
        {
            return Slurm(o, whole, schedule, console);
        }

        string results = o.Results ?? Path.Combine(folder, TournamentOutputs.Results);
        if (o.Results is null && Directory.Exists(folder) && !File.Exists(results) && Directory.EnumerateFileSystemEntries(folder).Any())
        {
            return Refuse(console, $"--out: {o.Out} is not empty and holds no {TournamentOutputs.Results}; give an empty or new folder (or one of the same tournament, to resume it)");
        }

        var header = whole with { ShardIndex = o.ShardIndex, ShardCount = o.ShardCount };
        try
        {
            // Another tournament's results are never touched: checked before anything is played.
            foreach (string file in o.Merge.Prepend(results))
            {
                if (File.Exists(file) && TournamentFile.Read(file).Header is var found && !found.SameSettings(whole))
                {
                    return Refuse(console, $"{file}: holds another tournament ({found.Difference(whole)}); use another --out or delete it");
                }
            }

            foreach (string file in o.Merge.Where(f => !File.Exists(f)))
            {
                return Refuse(console, $"--merge: {file} does not exist");
            }
        }
        catch (ResultFileException e)
        {
            return Refuse(console, e.Message);
        }

        try
        {
            Directory.CreateDirectory(o.Results is null ? folder : Path.GetDirectoryName(Path.GetFullPath(results))!);
            if (o.Replays && o.Results is null)
            {
                Directory.CreateDirectory(Path.Combine(folder, TournamentOutputs.Replays));
            }
        }
        catch (Exception e) when (e is IOException or UnauthorizedAccessException)
        {
            return Refuse(console, $"--out: cannot create {o.Out} ({e.Message})");
        }

        if (Seats(o, console) is not { } seats)
        {
            return ExitCodes.BadInput;
        }

        try
        {
            return o.Cup is { } cup ? PlayCup(o, header, cup, folder, results, seats, console) : Play(o, header, schedule, folder, results, seats, console);
        }
        finally
        {
            foreach (var seat in seats)
            {
                seat?.Dispose(); // a client that plays a series reads the end of the stream: no more matches
            }
        }
    }

    // Per entrant, the seat of a remote entrant (remote:PORT), bound now so that a port in use is bad input before
    // anything is played, and every seat's address said before any client is waited for; null (said) when one cannot be bound.
    private static RemoteSeat?[]? Seats(TournamentOptions o, CliConsole console)
    {
        var seats = new RemoteSeat?[o.Entrants.Count];
        if (o.AnyRemote && !System.Net.IPAddress.IsLoopback(o.RemoteHost))
        {
            console.ErrorLine($"tournament: warning: --remote-host {o.RemoteHost} is not a loopback address: any machine that reaches it may connect{(o.Entrants.Exists(e => e.RemotePort is not null && o.RemoteToken(e.Name) is null) ? " (give --remote-token)" : "")}");
        }

        for (int i = 0; i < seats.Length; i++)
        {
            var e = o.Entrants[i];
            if (e.RemotePort is not int port)
            {
                continue;
            }

            try
            {
                seats[i] = new RemoteSeat($"entrant {e.Name}", $"--entrant {e.Name}=remote", o.RemoteHost, port, o.RemoteToken(e.Name), TimeSpan.FromSeconds(o.RemoteWaitSeconds), console.ErrorLine);
            }
            catch (StrategyLoadException x)
            {
                foreach (var seat in seats)
                {
                    seat?.Dispose();
                }

                console.ErrorLine($"--entrant {e.Name}: {x.Message}");
                return null;
            }
        }

        foreach (var seat in seats)
        {
            seat?.Announce();
        }

        return seats;
    }

    private static int Play(TournamentOptions o, TournamentHeader header, TournamentSchedule schedule, string folder, string results, RemoteSeat?[] seats, CliConsole console)
    {
        HostSandbox.Warn = console.ErrorLine;
        var entrants = new EntrantLoader(o.Entrants, o.HostSettings, console.ErrorLine, seats);
        var errors = entrants.Errors;
        if (entrants.AnyHosted)
        {
            try
            {
                HostSandbox.Use(o.Sandbox); // the warning or the refusal, before anything is played
            }
            catch (StrategyLoadException e)
            {
                return Refuse(console, e.Message);
            }
        }

        for (int i = 0; i < errors.Count; i++)
        {
            if (errors[i] is { } error)
            {
                console.ErrorLine($"tournament: entrant {o.Entrants[i].Name} cannot be loaded and forfeits its matches: {error}");
            }
        }

        var (kept, dropped, remap) = TournamentResume.GatherAll(header, schedule, o.Merge.Prepend(results), errors);
        if (remap is not null && o.Results is null)
        {
            MoveReplays(folder, remap.Moved);
        }

        string? replays = o.Replays ? folder : null;
        var toPlay = schedule.Matches
            .Where(m => m.Index % header.ShardCount == header.ShardIndex)
            .Where(m => !kept.TryGetValue(m.Index, out var r) || (replays is not null && !r.IsForfeit && !File.Exists(TournamentOutputs.ReplayPage(replays, m.Index))))
            .ToList();
        foreach (var m in toPlay)
        {
            kept.Remove(m.Index);
        }

        int inShard = schedule.Matches.Count(m => m.Index % header.ShardCount == header.ShardIndex);
        string share = header.ShardCount > 1 ? string.Create(CultureInfo.InvariantCulture, $" (shard {header.ShardIndex}/{header.ShardCount}: {inShard})") : string.Empty;
        console.Out.Write(string.Create(CultureInfo.InvariantCulture,
            $"tournament: {header.Item}, {header.Entrants.Count} entrants, {Plural(header.Seeds, "seed")}, {Plural(header.Matches, "match")}{share}; {toPlay.Count} to play, {inShard - toPlay.Count} already there{(dropped > 0 ? $", {dropped} broken lines dropped" : string.Empty)}{(remap is { Changed: > 0 } ? $", {Plural(remap.Changed, "match")} of changed or removed entrants dropped" : string.Empty)}\n"));

        // What is already there is rewritten whole (dropping broken lines), then each finished match is appended.
        TournamentFile.Write(results, header, kept.Values.Where(r => r.Index % header.ShardCount == header.ShardIndex));
        if (Playing.Of(o, header, entrants, replays, console) is not (var runner, var threads, var interactive, var clock, var live))
        {
            return ExitCodes.BadInput;
        }

        using var page = live;
        var progress = interactive ? new ProgressBar(console.Out, toPlay.Count, "match", clock) : null;
        var failures = new List<string>();
        int done = 0, quarter = 0;
        using (var append = new FileStream(results, FileMode.Append, FileAccess.Write, FileShare.Read))
        {
            runner.Run(toPlay, threads, (m, record, failure) =>
            {
                done++;
                if (record is not null)
                {
                    kept[m.Index] = record;
                    TournamentFile.WriteRecord(append, record);
                    append.Flush();
                }

                if (failure is not null)
                {
                    failures.Add(string.Create(CultureInfo.InvariantCulture, $"match {m.Index}: {failure}"));
                }

                progress?.Update(done);
                if (progress is null && header.ShardCount == 1 && done * 4 / toPlay.Count > quarter)
                {
                    quarter = done * 4 / toPlay.Count;
                    console.Out.Write(string.Create(CultureInfo.InvariantCulture, $"played {done}/{toPlay.Count} matches\n"));
                }
            });
        }

        clock.Stop();
        progress?.Clear();
        var mine = kept.Values.Where(r => r.Index % header.ShardCount == header.ShardIndex).ToList();
        if (header.ShardCount > 1)
        {
            TournamentFile.Write(results, header, mine);
            console.Out.Write(string.Create(CultureInfo.InvariantCulture, $"shard {header.ShardIndex}/{header.ShardCount} finished: {mine.Count} of {inShard} matches in {results}\n"));
        }
        else
        {
            var standings = Standings.Compute(header, o.Item.TeamCount, mine, errors);
            TournamentOutputs.Write(folder, standings, mine, entrants.TeamNames);
            console.Out.Write(StandingsLines(standings));
            console.Out.Write(FaultLines(standings, o.Out, j => File.Exists(TournamentOutputs.ReplayPage(folder, j))));
            console.Out.Write(Wrote(o));
        }

        return Finish(console, clock.Elapsed, threads, toPlay.Count, header.Cycles, failures);
    }

    // --format groups-knockout: the group stage, then the knockout round by round as the results decide it.
    // What the folder holds is kept by match (seed and entrants, each in the same version), wherever the new layout puts it.
    private static int PlayCup(TournamentOptions o, TournamentHeader header, GroupsKnockout cup, string folder, string results, RemoteSeat?[] seats, CliConsole console)
    {
        HostSandbox.Warn = console.ErrorLine;
        var entrants = new EntrantLoader(o.Entrants, o.HostSettings, console.ErrorLine, seats);
        var errors = entrants.Errors;
        if (entrants.AnyHosted)
        {
            try
            {
                HostSandbox.Use(o.Sandbox);
            }
            catch (StrategyLoadException e)
            {
                return Refuse(console, e.Message);
            }
        }

        for (int i = 0; i < errors.Count; i++)
        {
            if (errors[i] is { } error)
            {
                console.ErrorLine($"tournament: entrant {o.Entrants[i].Name} cannot be loaded and forfeits its matches: {error}");
            }
        }

        var names = o.Entrants.Select(e => e.Name).ToArray();
        TournamentCupPool pool;
        try
        {
            pool = TournamentCupPool.Read(results, header, errors, folder);
        }
        catch (ResultFileException e)
        {
            return Refuse(console, e.Message);
        }

        console.Out.Write(string.Create(CultureInfo.InvariantCulture,
            $"tournament: {header.Item}, {header.Entrants.Count} entrants, {Plural(header.Seeds, "seed")}, groups-knockout: {Plural(cup.Groups.Count, "group")}, the top {cup.Advance} of each into the knockout, the final on {Plural(cup.FinalSeeds, "seed")}{(pool.Broken > 0 ? $"; {pool.Broken} broken lines dropped" : string.Empty)}{(pool.Changed > 0 ? $"; {Plural(pool.Changed, "match")} of changed or removed entrants dropped" : string.Empty)}\n"));
        TournamentFile.Write(results, header, pool.Records);
        string? replays = o.Replays ? folder : null;
        if (Playing.Of(o, header, entrants, replays, console) is not (var runner, var threads, var interactive, var clock, var live))
        {
            return ExitCodes.BadInput;
        }

        using var page = live;
        var failures = new List<string>();
        int shown = 0, playedAll = 0;
        Bracket bracket;
        using (var append = new FileStream(results, FileMode.Append, FileAccess.Write, FileShare.Read))
        {
            while (true)
            {
                bracket = cup.Unfold(names, pool.Find);
                var toPlay = new List<ScheduledMatch>();
                for (; shown < bracket.Steps.Count; shown++)
                {
                    var step = bracket.Steps[shown];
                    var missing = step.Matches.Where(m => !pool.Has(m) || (replays is not null && !pool.HasReplay(m))).ToList();
                    console.Out.Write(string.Create(CultureInfo.InvariantCulture, $"{step.Label}: {Plural(step.Matches.Count, "match")}; {missing.Count} to play, {step.Matches.Count - missing.Count} already there\n"));
                    toPlay.AddRange(missing);
                }

                if (toPlay.Count == 0)
                {
                    break;
                }

                var progress = interactive ? new ProgressBar(console.Out, toPlay.Count, "match", clock) : null;
                int done = 0;
                runner.Run(toPlay, threads, (m, record, failure) =>
                {
                    done++;
                    if (record is not null)
                    {
                        pool.Add(m, record);
                        TournamentFile.WriteRecord(append, record);
                        append.Flush();
                    }

                    if (failure is not null)
                    {
                        failures.Add(string.Create(CultureInfo.InvariantCulture, $"match {m.Index}: {failure}"));
                    }

                    progress?.Update(done);
                });
                progress?.Clear();
                playedAll += toPlay.Count;
                if (bracket.Complete)
                {
                    break; // the last step was only replays to write again
                }
            }
        }

        clock.Stop();
        pool.PlaceReplays(bracket);
        bracket = cup.Unfold(names, pool.Find);
        var records = bracket.Matches.Select(m => pool.At(m)).ToList();
        var final = header with { Matches = bracket.Matches.Count };
        var standings = Standings.Compute(final, 2, records, errors) with { Cup = bracket };
        TournamentOutputs.Write(folder, standings, records, entrants.TeamNames);
        console.Out.Write(StandingsLines(standings));
        console.Out.Write(CupLines(standings));
        console.Out.Write(FaultLines(standings, o.Out, j => File.Exists(TournamentOutputs.ReplayPage(folder, j))));
        console.Out.Write(Wrote(o));
        return Finish(console, clock.Elapsed, threads, playedAll, header.Cycles, failures);
    }

    // What a finished tournament wrote into its folder.
    private static string Wrote(TournamentOptions o) =>
        $"wrote {TournamentOutputs.Results}, {TournamentOutputs.StandingsJsonName}, {TournamentOutputs.StandingsMarkdownName}, {TournamentOutputs.StandingsCsvName}, {TournamentOutputs.MatchesCsvName} and {TournamentOutputs.Report}{(o.Replays ? " and replays/" : string.Empty)} in {o.Out}\n";

    // The wall-time line of the PLAYED matches of CYCLES each, then the first failures inside the server; the exit code.
    // How the matches are played: the runner, matches at once, whether the terminal shows a progress
    // bar, the clock, and with --live the page they play in one at a time; null when the page's port cannot be used.
    private sealed record Playing(TournamentRunner Runner, int Threads, bool Interactive, Stopwatch Clock, LiveTournament? Live)
    {
        public static Playing? Of(TournamentOptions o, TournamentHeader header, EntrantLoader entrants, string? replays, CliConsole console)
        {
            var live = o.Live ? LiveTournament.Open(o.Host, o.Port, o.Speed, console) : null;
            if (o.Live && live is null)
            {
                return null;
            }

            var runner = new TournamentRunner(o.Item, header, entrants, replays is null ? null : j => TournamentOutputs.ReplayPage(replays, j)) { Player = live is null ? null : live.Play };
            bool interactive = live is null && ReferenceEquals(console.Out, Console.Out) && !Console.IsOutputRedirected;
            // A remote entrant's client plays one match at a time: with one, the matches are played one after another.
            return new Playing(runner, live is null && !o.AnyRemote ? o.Threads ?? Environment.ProcessorCount : 1, interactive, Stopwatch.StartNew(), live);
        }
    }

    private static int Finish(CliConsole console, TimeSpan elapsed, int threads, int played, int cycles, List<string> failures)
    {
        double seconds = Math.Max(elapsed.TotalSeconds, 1e-9);
        console.Out.Write(string.Create(CultureInfo.InvariantCulture, $"wall time: {seconds:0.000} s on {threads} threads, {played / seconds:0.00} matches/s, {played * cycles * 0.1 / seconds:0}x real time\n"));
        foreach (string f in failures.Take(5))
        {
            console.ErrorLine("tournament: " + f);
        }

        if (failures.Count > 0)
        {
            console.ErrorLine($"tournament: {failures.Count} matches failed inside the server; each is recorded as a forfeit of the team at fault");
            return ExitCodes.InternalError;
        }

        return ExitCodes.Success;
    }

    // The groups' tables and the bracket in a few lines for the terminal.
    private static string CupLines(Standings s)
    {
        if (s.Cup is not { } cup)
        {
            return string.Empty;
        }

        var t = new System.Text.StringBuilder();
        foreach (var group in cup.Groups)
        {
            t.Append("group ").Append(group.Name).Append(": ")
                .Append(string.Join(", ", group.Table.Select(p => string.Create(CultureInfo.InvariantCulture, $"{p.Rank} {p.Name} {p.Points} pts ({StandingsText.Signed(p.GoalDifference)})"))))
                .Append('\n');
        }

        t.Append("knockout (").Append(StandingsText.KnockoutRule).Append("):\n");
        foreach (var round in cup.Rounds)
        {
            foreach (var tie in round.Ties)
            {
                t.Append("  ").Append(round.Name).Append(": ").Append(StandingsText.Pairing(s, tie));
                if (tie.A is not null && tie.B is not null)
                {
                    t.Append(": wins ").Append(StandingsText.Pair(tie.WinsA, tie.WinsB)).Append(", goals ").Append(StandingsText.Pair(tie.GoalsA, tie.GoalsB));
                }

                t.Append(" -> ").Append(StandingsText.GoesOn(s, tie)).Append(" (").Append(tie.DecidedBy ?? "not decided").Append(")\n");
            }
        }

        t.Append("champion: ").Append(cup.Champion is null ? "not decided yet" : s.Header.Entrants[cup.Champion.Entrant].Name).Append('\n');
        return t.ToString();
    }

    // --check: each entrant loads and plays one short match against idle; the table on stdout, nothing written.
    private static int CheckEntrants(TournamentOptions o, CliConsole console)
    {
        HostSandbox.Warn = console.ErrorLine;
        var entrants = o.Entrants.Append(new Entrant("idle", "idle")).ToList();
        var loader = new EntrantLoader(entrants, o.HostSettings, console.ErrorLine);
        if (loader.AnyHosted)
        {
            try
            {
                HostSandbox.Use(o.Sandbox);
            }
            catch (StrategyLoadException e)
            {
                return Refuse(console, e.Message);
            }
        }

        var lines = EntrantCheck.Run(o.Item, entrants, loader, o.Cycles, o.FirstSeed, o.StrategyTimeoutMs);
        console.Out.Write(EntrantCheck.Format(lines, o.Item, o.Cycles, o.FirstSeed));
        return ExitCodes.Success;
    }

    // The replay pages of the matches kept from a run with other entrants, moved to their new index;
    // the pages of matches not kept are deleted (their index may now be another match's).
    private static void MoveReplays(string folder, Dictionary<int, int> moved)
    {
        string pages = Path.Combine(folder, TournamentOutputs.Replays);
        if (!Directory.Exists(pages))
        {
            return;
        }

        var staged = new List<(string From, int To)>();
        foreach (string page in Directory.EnumerateFiles(pages, "match-*.html"))
        {
            string number = Path.GetFileNameWithoutExtension(page)["match-".Length..];
            if (int.TryParse(number, NumberStyles.None, CultureInfo.InvariantCulture, out int index) && moved.TryGetValue(index, out int to))
            {
                string temporary = page + ".moving";
                File.Move(page, temporary, overwrite: true);
                staged.Add((temporary, to));
            }
            else
            {
                File.Delete(page);
            }
        }

        foreach (var (from, to) in staged)
        {
            File.Move(from, TournamentOutputs.ReplayPage(folder, to), overwrite: true);
        }
    }

    // The standings in a few lines for the terminal.
    private static string StandingsLines(Standings s)
    {
        var t = new System.Text.StringBuilder();
        int width = Math.Max(7, s.Rows.Max(r => r.Name.Length));
        bool one = s.Teams == 1;
        t.Append(string.Create(CultureInfo.InvariantCulture, $"{"rank",4}  {"entrant".PadRight(width)}  {(one ? "score" : "rating"),8}  {"95 % interval",-21}  {(one ? "played" : "W-D-L"),-11}  overlaps\n"));
        foreach (var r in s.Rows)
        {
            string record = one ? r.Played.ToString(CultureInfo.InvariantCulture) : string.Create(CultureInfo.InvariantCulture, $"{r.Wins}-{r.Draws}-{r.Losses}");
            t.Append(string.Create(CultureInfo.InvariantCulture, $"{r.Rank,4}  {r.Name.PadRight(width)}  {StandingsText.Value(s, r.Rating),8}  {StandingsText.Interval(s, r.Interval),-21}  {record,-11}  {StandingsText.Overlaps(r)}{(r.Error is null ? string.Empty : "  (not loaded)")}\n"));
        }

        if (StandingsText.Ties(s) is { } ties)
        {
            t.Append(ties).Append('\n');
        }

        if (s.Points.Count > 0)
        {
            t.Append("points table (").Append(StandingsText.PointsRule).Append("):\n");
            t.Append(string.Create(CultureInfo.InvariantCulture, $"{"rank",4}  {"entrant".PadRight(width)}  {"played",6}  {"W-D-L",-11}  {"goals",-7}  {"diff",4}  {"points",6}\n"));
            foreach (var p in s.Points)
            {
                string wdl = string.Create(CultureInfo.InvariantCulture, $"{p.Won}-{p.Drawn}-{p.Lost}");
                string goals = string.Create(CultureInfo.InvariantCulture, $"{p.GoalsFor}:{p.GoalsAgainst}");
                t.Append(string.Create(CultureInfo.InvariantCulture, $"{p.Rank,4}  {p.Name.PadRight(width)}  {p.Played,6}  {wdl,-11}  {goals,-7}  {StandingsText.Signed(p.GoalDifference),4}  {p.Points,6}\n"));
            }
        }

        return t.ToString();
    }

    // The entrants' runtime faults, one line each, with the first fault's place in its replay page when it has one; nothing when none had a fault.
    private static string FaultLines(Standings s, string folder, Func<int, bool> hasReplay)
    {
        if (!s.AnyFaults)
        {
            return string.Empty;
        }

        var t = new System.Text.StringBuilder("runtime faults (exceptions, timeouts, bad answers, host ends):\n");
        foreach (var r in s.Rows)
        {
            if (r.Faults is { } f)
            {
                t.Append("  ").Append(r.Name).Append(": ").Append(StandingsText.Faults(f));
                if (hasReplay(f.FirstMatch))
                {
                    t.Append(" (").Append(Path.Combine(folder, f.ReplayLink())).Append(')');
                }

                t.Append('\n');
            }
        }

        return t.ToString();
    }

    // --slurm SDIR: the shards still to play (their files in SDIR missing or incomplete), as a job array and a merge job.
    private static int Slurm(TournamentOptions o, TournamentHeader whole, TournamentSchedule schedule, CliConsole console)
    {
        string jobs;
        try
        {
            jobs = Path.TrimEndingDirectorySeparator(Path.GetFullPath(o.Slurm!));
        }
        catch (Exception e) when (e is ArgumentException or NotSupportedException or PathTooLongException)
        {
            return Refuse(console, $"--slurm: not a usable path ({e.Message})");
        }

        if (File.Exists(jobs))
        {
            return Refuse(console, $"--slurm: {o.Slurm} is a file, not a folder");
        }

        if (o.Submit && (SlurmRun.OnPath("sbatch") is null || SlurmRun.OnPath("bash") is null))
        {
            return Refuse(console, "--submit: sbatch (or bash) is not on PATH; submit from a Slurm login node, or leave out --submit and run submit.sh there");
        }

        int shards = Math.Min(o.SlurmShards ?? SlurmJob.DefaultShards(schedule.Matches.Count), schedule.Matches.Count);
        var toPlay = new List<int>();
        try
        {
            for (int i = 0; i < shards; i++)
            {
                if (!TournamentShards.Complete(Path.Combine(jobs, ShardResults.FileName(i)), whole, schedule, i, shards))
                {
                    toPlay.Add(i);
                }
            }

            string results = Path.Combine(Path.GetFullPath(o.Out), TournamentOutputs.Results);
            if (File.Exists(results) && TournamentFile.Read(results).Header is var found && !found.SameTournament(whole))
            {
                return Refuse(console, $"{results}: holds another tournament ({found.Difference(whole)}); use another --out or delete it");
            }
        }
        catch (ResultFileException e)
        {
            return Refuse(console, e.Message);
        }

        if (SlurmRun.Setup(o.SlurmSetup, console, "tournament") is not { } setup)
        {
            return ExitCodes.BadInput;
        }

        var server = ServerCommand.OfThisProcess();
        var job = new SlurmJob(
            server, o.PassedOn, Environment.CurrentDirectory, jobs, Path.Combine(Path.GetFullPath(o.Out), TournamentOutputs.Results), shards, toPlay,
            o.Threads ?? 1, o.Threads is not null, o.Partition, o.TimeLimit, "tournament", ["tournament", .. o.PassedOn, "--merge"],
            o.SbatchArguments, setup.Length > 0 ? setup : null);
        return SlurmRun.WriteJobs(job, schedule.Matches.Count, o.Submit, console, "tournament");
    }

    private static string Plural(int count, string noun) =>
        string.Create(CultureInfo.InvariantCulture, $"{count} {noun}{(count == 1 ? string.Empty : noun.EndsWith('h') ? "es" : "s")}");

    private static int Refuse(CliConsole console, string message)
    {
        console.ErrorLine("tournament: " + message);
        return ExitCodes.BadInput;
    }

    private static string HelpText() =>
        $"Usage: {CliApp.ProgramName} {TournamentOptions.Usage}\n\n" +
        "Plays a tournament of a competition item between the entrants (NAME=SPEC: SPEC is demo, the item's demo\n" +
        "strategy, a built-in (idle, chase-ball), a .dll, a .cs file or a folder of .cs files). Two-team items: every\n" +
        "ordered pair of entrants (both sides of the field) on each of --seeds N seeds (default 4) from --seed S\n" +
        "(default 1); one-team items: every entrant on each seed. --minutes 10|5|3|1 (default 10) or --cycles N sets\n" +
        "the length; --threads P plays P matches at once (default: every core). Writes into --out DIR: results.jsonl\n" +
        "(the batch format plus the entrants), standings.json, standings.md, standings.csv, matches.csv and\n" +
        "report.html (--replays: and every match's replay page in replays/). Run again into the same DIR, it plays\n" +
        "only missing or broken matches, and those of entrants whose code changed (each file or folder entrant has a\n" +
        "version, a hash of its files) or that were added. --entrants-dir DIR: every sub-folder, .cs file and .dll\n" +
        "in DIR is an entrant named after it.\n" +
        "--check: each entrant only loads and plays one match of at most a minute against idle; a table, nothing written.\n" +
        "--live: a projector view: the matches play one after another in the live page (--port N, default 8080; --host H;\n" +
        "--speed X times real time) and are recorded as they end; on an address other machines reach, viewers only\n" +
        "watch unless they hold the control link printed at start.\n" +
        "--format groups-knockout: snake-seeded groups (--groups G, default 2; --seeding NAME,... to seed by another\n" +
        "order) play round robins ranked by the points table; the top --advance K (default 2) of each go into a\n" +
        "single-elimination bracket (cross-over pairing, byes for the best seeds), each pairing both sides on --seeds\n" +
        "seeds, the final on --final-seeds F; a pairing goes by wins, then goal difference, then a further seed, then\n" +
        "the better seed. Played on one machine.\n" +
        "Two-team ratings: Bradley-Terry (a draw is half a win) on the Elo scale, mean 1500, with 95 % bootstrap\n" +
        "intervals, and a points table (3 a win, 1 a draw; goal difference, goals, head to head); one-team: mean score\n" +
        "with 95 % bootstrap intervals. An entrant that cannot be loaded forfeits.\n" +
        "Entrants' code runs as with 'run': each in its own strategy host per match (--isolation process, the default;\n" +
        "--sandbox auto|required|off, --strategy-memory MB), or in the server's process with --isolation none; faults\n" +
        "are charged to the team that made them and the match is played.\n" +
        "NAME=remote:PORT: a remote entrant, played by a client that connects once (connect, or any client of\n" +
        "docs/protocol.md) and plays its matches in turn; --remote-wait SECONDS (default 60), --remote-host ADDR and\n" +
        "--remote-token [NAME=]TOKEN as run's; with one, the matches are played one at a time.\n" +
        "--slurm SDIR writes the tournament as a Slurm job array of --shards K tasks (--shard I/K --results FILE each)\n" +
        "and a merge job (--merge FILE...) into SDIR (--partition, --time, --sbatch-arg ARG for any other sbatch\n" +
        "option, --slurm-setup FILE sourced by the jobs first); --submit submits them.\n" +
        "Formats: docs/tournament.md.\n";
}
