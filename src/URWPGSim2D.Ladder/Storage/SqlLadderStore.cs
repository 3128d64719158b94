using System;
using System.Collections.Generic;
using System.Data;
using System.Data.Common;
using System.Globalization;

namespace URWPGSim2D.Ladder.Storage;

/// <summary>
/// The ladder's rows in a SQL database through ADO.NET: one connection per operation (the
/// provider pools them), each change one statement or one transaction. The dialect gives the
/// schema's migrations and the few statements that differ between SQLite and PostgreSQL.
/// Times are kept as UTC text (ISO 8601), seeds as their 64 bits in a signed integer.
/// </summary>
internal sealed class SqlLadderStore : ILadderStore
{
    private readonly Func<DbConnection> _connect;
    private readonly SqlDialect _dialect;
    private readonly IDisposable? _owned;

    /// <summary>A store over connections made by <paramref name="connect"/> (not yet open); <paramref name="owned"/> (the connections' pool) is disposed with it.</summary>
    public SqlLadderStore(Func<DbConnection> connect, SqlDialect dialect, IDisposable? owned = null)
    {
        _connect = connect;
        _dialect = dialect;
        _owned = owned;
    }

    /// <summary>The database's dialect.</summary>
    public SqlDialect Dialect => _dialect;

    /// <inheritdoc/>
    public void Migrate()
    {
        using var c = Open();
        using var t = c.BeginTransaction();
        if (_dialect.MigrationLock is { } gate)
        {
            Execute(c, t, gate);
        }

        Execute(c, t, "CREATE TABLE IF NOT EXISTS schema_version (version INTEGER NOT NULL)");
        int version = Convert.ToInt32(Scalar(c, t, "SELECT COALESCE(MAX(version), 0) FROM schema_version"), CultureInfo.InvariantCulture);
        var migrations = _dialect.Migrations;
        for (int v = version; v < migrations.Count; v++)
        {
            foreach (string statement in migrations[v])
            {
                Execute(c, t, statement);
            }

            Execute(c, t, "INSERT INTO schema_version (version) VALUES (@v)", ("v", v + 1));
        }

        t.Commit();
    }

    /// <inheritdoc/>
    public int SchemaVersion()
    {
        using var c = Open();
        return Convert.ToInt32(Scalar(c, null, "SELECT COALESCE(MAX(version), 0) FROM schema_version"), CultureInfo.InvariantCulture);
    }

    /// <inheritdoc/>
    public string? Setting(string key)
    {
        using var c = Open();
        return Scalar(c, null, "SELECT value FROM settings WHERE key = @k", ("k", key)) as string;
    }

    /// <inheritdoc/>
    public void SetSetting(string key, string value)
    {
        using var c = Open();
        Execute(c, null, "INSERT INTO settings (key, value) VALUES (@k, @v) ON CONFLICT (key) DO UPDATE SET value = excluded.value", ("k", key), ("v", value));
    }

    /// <inheritdoc/>
    public LadderRow OpenLadder(string item, int cycles, ulong firstSeed)
    {
        using var c = Open();
        using var t = c.BeginTransaction();
        var found = One(c, t, LadderSelect + " WHERE item = @i ORDER BY id LIMIT 1", ReadLadder, ("i", item));
        if (found is null)
        {
            Execute(c, t, "INSERT INTO ladders (item, cycles, first_seed, paused, created) VALUES (@i, @c, @s, 0, @t)",
                ("i", item), ("c", cycles), ("s", unchecked((long)firstSeed)), ("t", Now()));
            found = One(c, t, LadderSelect + " WHERE item = @i ORDER BY id LIMIT 1", ReadLadder, ("i", item))!;
        }

        t.Commit();
        return found;
    }

    /// <inheritdoc/>
    public LadderRow CreateLadder(string item, int cycles, ulong firstSeed)
    {
        using var c = Open();
        using var t = c.BeginTransaction();
        long id = Convert.ToInt64(Scalar(c, t, "INSERT INTO ladders (item, cycles, first_seed, paused, created) VALUES (@i, @c, @s, 0, @t) RETURNING id",
            ("i", item), ("c", cycles), ("s", unchecked((long)firstSeed)), ("t", Now())), CultureInfo.InvariantCulture);
        var row = One(c, t, LadderSelect + " WHERE id = @id", ReadLadder, ("id", id))!;
        t.Commit();
        return row;
    }

    /// <inheritdoc/>
    public IReadOnlyList<LadderRow> Ladders()
    {
        using var c = Open();
        return All(c, null, LadderSelect + " ORDER BY id", ReadLadder);
    }

    private const string LadderSelect = "SELECT id, item, cycles, first_seed, paused, created FROM ladders";

    /// <inheritdoc/>
    public LadderRow? NewestLadder()
    {
        using var c = Open();
        return One(c, null, LadderSelect + " ORDER BY id DESC LIMIT 1", ReadLadder);
    }

    /// <inheritdoc/>
    public LadderRow? Ladder(long id)
    {
        using var c = Open();
        return One(c, null, LadderSelect + " WHERE id = @id", ReadLadder, ("id", id));
    }

    /// <inheritdoc/>
    public void SetPaused(long ladder, bool paused)
    {
        using var c = Open();
        Execute(c, null, "UPDATE ladders SET paused = @p WHERE id = @id", ("p", paused ? 1 : 0), ("id", ladder));
    }

    /// <inheritdoc/>
    public void SetCycles(long ladder, int cycles)
    {
        using var c = Open();
        Execute(c, null, "UPDATE ladders SET cycles = @c WHERE id = @id", ("c", cycles), ("id", ladder));
    }

    /// <inheritdoc/>
    public TeamRow? AddTeam(string name, string tokenHash, string? house, long ladder)
    {
        using var c = Open();
        using var t = c.BeginTransaction();
        if (One(c, t, "SELECT id FROM teams WHERE name = @n", r => r.GetInt64(0), ("n", name)) != 0)
        {
            return null;
        }

        Execute(c, t, "INSERT INTO teams (name, token_hash, password_hash, house, created, ladder_id) VALUES (@n, @h, NULL, @s, @t, @l)",
            ("n", name), ("h", tokenHash), ("s", house), ("t", Now()), ("l", ladder == 0 ? null : ladder));
        var team = One(c, t, TeamSelect + " WHERE name = @n", ReadTeam, ("n", name));
        t.Commit();
        return team;
    }

    /// <inheritdoc/>
    public void SetPassword(long team, string passwordHash)
    {
        using var c = Open();
        Execute(c, null, "UPDATE teams SET password_hash = @p WHERE id = @id", ("p", passwordHash), ("id", team));
    }

    private const string TeamSelect = "SELECT id, name, token_hash, password_hash, house, created, ladder_id FROM teams";

    /// <inheritdoc/>
    public IReadOnlyList<TeamRow> Teams()
    {
        using var c = Open();
        return All(c, null, TeamSelect + " ORDER BY id", ReadTeam);
    }

    /// <inheritdoc/>
    public TeamRow? TeamByToken(string tokenHash)
    {
        using var c = Open();
        return One(c, null, TeamSelect + " WHERE token_hash = @h", ReadTeam, ("h", tokenHash));
    }

    /// <inheritdoc/>
    public TeamRow? TeamByName(string name)
    {
        using var c = Open();
        return One(c, null, TeamSelect + " WHERE name = @n", ReadTeam, ("n", name));
    }

    /// <inheritdoc/>
    public void AddSession(long team, string tokenHash)
    {
        using var c = Open();
        Execute(c, null, "INSERT INTO sessions (token_hash, team_id, created) VALUES (@h, @t, @c)", ("h", tokenHash), ("t", team), ("c", Now()));
    }

    /// <inheritdoc/>
    public TeamRow? TeamBySession(string tokenHash)
    {
        using var c = Open();
        return One(c, null, "SELECT t.id, t.name, t.token_hash, t.password_hash, t.house, t.created, t.ladder_id FROM sessions s JOIN teams t ON t.id = s.team_id WHERE s.token_hash = @h", ReadTeam, ("h", tokenHash));
    }

    private const string SubmissionSelect = "SELECT id, team_id, created, kind, path, state, log, ladder_id FROM submissions";

    /// <inheritdoc/>
    public SubmissionRow AddSubmission(long team, long ladder, string kind, DateTime created)
    {
        using var c = Open();
        using var t = c.BeginTransaction();
        long id = Convert.ToInt64(Scalar(c, t, "INSERT INTO submissions (team_id, ladder_id, created, kind, path, state, log) VALUES (@t, @l, @c, @k, '', @s, '') RETURNING id",
            ("t", team), ("l", ladder), ("c", Time(created)), ("k", kind), ("s", SubmissionRow.Checking)), CultureInfo.InvariantCulture);
        var row = One(c, t, SubmissionSelect + " WHERE id = @id", ReadSubmission, ("id", id))!;
        t.Commit();
        return row;
    }

    /// <inheritdoc/>
    public void SetSubmissionPath(long submission, string path)
    {
        using var c = Open();
        Execute(c, null, "UPDATE submissions SET path = @p WHERE id = @id", ("p", path), ("id", submission));
    }

    /// <inheritdoc/>
    public void SetSubmissionFiles(long submission, string path, IReadOnlyList<StoredFile> files)
    {
        using var c = Open();
        using var t = c.BeginTransaction();
        Execute(c, t, "DELETE FROM submission_files WHERE submission_id = @id", ("id", submission));
        InsertFiles(c, t, "submission_files", "submission_id", submission, files);
        Execute(c, t, "UPDATE submissions SET path = @p WHERE id = @id", ("p", path), ("id", submission));
        t.Commit();
    }

    /// <inheritdoc/>
    public IReadOnlyList<StoredFile> SubmissionFiles(long submission)
    {
        using var c = Open();
        return All(c, null, "SELECT name, sha256, bytes FROM submission_files WHERE submission_id = @id ORDER BY name", ReadFile, ("id", submission));
    }

    /// <inheritdoc/>
    public IReadOnlyList<SubmissionRow> SubmissionsWithoutFiles()
    {
        using var c = Open();
        return All(c, null, SubmissionSelect + " s WHERE path <> '' AND NOT EXISTS (SELECT 1 FROM submission_files f WHERE f.submission_id = s.id) ORDER BY id", ReadSubmission);
    }

    /// <inheritdoc/>
    public void FinishSubmission(long submission, bool ok, string log)
    {
        using var c = Open();
        Execute(c, null, "UPDATE submissions SET state = @s, log = @l WHERE id = @id",
            ("s", ok ? SubmissionRow.Ok : SubmissionRow.Error), ("l", log), ("id", submission));
    }

    /// <inheritdoc/>
    public SubmissionRow? Submission(long id)
    {
        using var c = Open();
        return One(c, null, SubmissionSelect + " WHERE id = @id", ReadSubmission, ("id", id));
    }

    /// <inheritdoc/>
    public IReadOnlyList<SubmissionRow> Submissions(long? team)
    {
        using var c = Open();
        return team is { } id
            ? All(c, null, SubmissionSelect + " WHERE team_id = @t ORDER BY id DESC", ReadSubmission, ("t", id))
            : All(c, null, SubmissionSelect + " ORDER BY id DESC", ReadSubmission);
    }

    /// <inheritdoc/>
    public int SubmissionsSince(long team, long ladder, DateTime since)
    {
        using var c = Open();
        return Convert.ToInt32(Scalar(c, null, "SELECT COUNT(*) FROM submissions WHERE team_id = @t AND ladder_id = @l AND created >= @s", ("t", team), ("l", ladder), ("s", Time(since))), CultureInfo.InvariantCulture);
    }

    /// <inheritdoc/>
    public SubmissionRow? NewestWorking(long team, long ladder)
    {
        using var c = Open();
        return One(c, null, SubmissionSelect + " WHERE team_id = @t AND ladder_id = @l AND state = @s ORDER BY id DESC LIMIT 1", ReadSubmission, ("t", team), ("l", ladder), ("s", SubmissionRow.Ok));
    }

    private const string MatchSelect = "SELECT id, ladder_id, seed, team_a, team_b, sub_a, sub_b, state, created, started, finished, record, final FROM matches";

    /// <inheritdoc/>
    public MatchRow AddMatch(long ladder, IReadOnlyList<long> teams, IReadOnlyList<long> submissions, bool final, Func<long, ulong> seedOf)
    {
        using var c = Open();
        using var t = c.BeginTransaction();
        long id = Convert.ToInt64(Scalar(c, t,
            "INSERT INTO matches (ladder_id, seed, team_a, team_b, sub_a, sub_b, state, created, final) VALUES (@l, 0, @ta, @tb, @sa, @sb, @s, @c, @f) RETURNING id",
            ("l", ladder), ("ta", teams[0]), ("tb", teams[1]), ("sa", submissions[0]), ("sb", submissions[1]), ("s", MatchRow.Queued), ("c", Now()), ("f", final ? 1 : 0)), CultureInfo.InvariantCulture);
        Execute(c, t, "UPDATE matches SET seed = @s WHERE id = @id", ("s", unchecked((long)seedOf(id))), ("id", id));
        var row = One(c, t, MatchSelect + " WHERE id = @id", ReadMatch, ("id", id))!;
        t.Commit();
        return row;
    }

    /// <inheritdoc/>
    public MatchRow? ClaimNext(long ladder)
    {
        using var c = Open();
        using var t = c.BeginTransaction();
        long id = One(c, t, _dialect.NextQueued, r => r.GetInt64(0), ("l", ladder), ("q", MatchRow.Queued));
        if (id == 0)
        {
            return null;
        }

        int changed = Execute(c, t, "UPDATE matches SET state = @r, started = @t WHERE id = @id AND state = @q", ("r", MatchRow.Running), ("t", Now()), ("id", id), ("q", MatchRow.Queued));
        var row = changed == 1 ? One(c, t, MatchSelect + " WHERE id = @id", ReadMatch, ("id", id)) : null;
        t.Commit();
        return row;
    }

    /// <inheritdoc/>
    public bool Claim(long match)
    {
        using var c = Open();
        return Execute(c, null, "UPDATE matches SET state = @r, started = @t WHERE id = @id AND state = @q", ("r", MatchRow.Running), ("t", Now()), ("id", match), ("q", MatchRow.Queued)) == 1;
    }

    /// <inheritdoc/>
    public bool ClaimForJob(long match, string job)
    {
        using var c = Open();
        return Execute(c, null, "UPDATE matches SET state = @r, started = @t, job = @j WHERE id = @id AND (state = @q OR (state = @r AND job = @j))",
            ("r", MatchRow.Running), ("t", Now()), ("j", job), ("id", match), ("q", MatchRow.Queued)) == 1;
    }

    /// <inheritdoc/>
    public void SetJob(long match, string job)
    {
        using var c = Open();
        Execute(c, null, "UPDATE matches SET job = @j WHERE id = @id AND job IS NULL", ("j", job), ("id", match));
    }

    /// <inheritdoc/>
    public IReadOnlyList<long> Unscheduled(long ladder)
    {
        using var c = Open();
        return All(c, null, "SELECT id FROM matches WHERE ladder_id = @l AND state = @q AND job IS NULL ORDER BY final DESC, id", r => r.GetInt64(0), ("l", ladder), ("q", MatchRow.Queued));
    }

    /// <inheritdoc/>
    public bool FinishMatch(long match, string record, IReadOnlyList<StoredFile>? files = null)
    {
        using var c = Open();
        using var t = c.BeginTransaction();
        int changed = Execute(c, t, "UPDATE matches SET state = @d, finished = @t, record = @rec WHERE id = @id AND state = @r",
            ("d", MatchRow.Done), ("t", Now()), ("rec", record), ("id", match), ("r", MatchRow.Running));
        if (changed == 1 && files is not null)
        {
            Execute(c, t, "DELETE FROM match_files WHERE match_id = @id", ("id", match));
            InsertFiles(c, t, "match_files", "match_id", match, files);
        }

        t.Commit();
        return changed == 1;
    }

    /// <inheritdoc/>
    public IReadOnlyList<(string Name, string Sha256)> MatchFileHashes(long match)
    {
        using var c = Open();
        return All(c, null, "SELECT name, sha256 FROM match_files WHERE match_id = @id ORDER BY name", r => (r.GetString(0), r.GetString(1)), ("id", match));
    }

    /// <inheritdoc/>
    public StoredFile? MatchFile(long match, string name)
    {
        using var c = Open();
        return One(c, null, "SELECT name, sha256, bytes FROM match_files WHERE match_id = @id AND name = @n", ReadFile, ("id", match), ("n", name));
    }

    /// <inheritdoc/>
    public bool AddMatchFiles(long match, IReadOnlyList<StoredFile> files)
    {
        using var c = Open();
        using var t = c.BeginTransaction();
        bool add = One(c, t, "SELECT id FROM matches WHERE id = @id AND state = @d AND NOT EXISTS (SELECT 1 FROM match_files WHERE match_id = @id)",
            r => r.GetInt64(0), ("id", match), ("d", MatchRow.Done)) == match;
        if (add)
        {
            InsertFiles(c, t, "match_files", "match_id", match, files);
        }

        t.Commit();
        return add;
    }

    /// <inheritdoc/>
    public IReadOnlyList<long> MatchesWithoutFiles()
    {
        using var c = Open();
        return All(c, null, "SELECT id FROM matches m WHERE state = @d AND NOT EXISTS (SELECT 1 FROM match_files f WHERE f.match_id = m.id) ORDER BY id",
            r => r.GetInt64(0), ("d", MatchRow.Done));
    }

    private static void InsertFiles(DbConnection c, DbTransaction t, string table, string key, long id, IReadOnlyList<StoredFile> files)
    {
        foreach (var f in files)
        {
            Execute(c, t, $"INSERT INTO {table} ({key}, name, sha256, bytes) VALUES (@id, @n, @h, @b)", ("id", id), ("n", f.Name), ("h", f.Sha256), ("b", f.Packed()));
        }
    }

    private static StoredFile ReadFile(DbDataReader r) => StoredFile.Unpacked(r.GetString(0), r.GetString(1), (byte[])r.GetValue(2));

    /// <inheritdoc/>
    public int RequeueRunning()
    {
        using var c = Open();
        return Execute(c, null, "UPDATE matches SET state = @q, started = NULL WHERE state = @r", ("q", MatchRow.Queued), ("r", MatchRow.Running));
    }

    /// <inheritdoc/>
    public bool Requeue(long match)
    {
        using var c = Open();
        using var t = c.BeginTransaction();
        bool requeued = Execute(c, t, "UPDATE matches SET state = @q, started = NULL, finished = NULL, record = NULL, job = NULL WHERE id = @id AND state = @d",
            ("q", MatchRow.Queued), ("id", match), ("d", MatchRow.Done)) == 1;
        if (requeued)
        {
            Execute(c, t, "DELETE FROM match_files WHERE match_id = @id", ("id", match));
        }

        t.Commit();
        return requeued;
    }

    /// <inheritdoc/>
    public MatchRow? Match(long id)
    {
        using var c = Open();
        return One(c, null, MatchSelect + " WHERE id = @id", ReadMatch, ("id", id));
    }

    /// <inheritdoc/>
    public IReadOnlyList<MatchRow> Matches(long ladder, IReadOnlyCollection<string> states, int limit)
    {
        using var c = Open();
        var names = new List<string>();
        var parameters = new List<(string, object?)> { ("l", ladder), ("n", limit) };
        int k = 0;
        foreach (string state in states)
        {
            names.Add("@s" + k.ToString(CultureInfo.InvariantCulture));
            parameters.Add(("s" + k.ToString(CultureInfo.InvariantCulture), state));
            k++;
        }

        string where = names.Count == 0 ? string.Empty : " AND state IN (" + string.Join(", ", names) + ")";
        return All(c, null, MatchSelect + " WHERE ladder_id = @l" + where + " ORDER BY id DESC LIMIT @n", ReadMatch, [.. parameters]);
    }

    /// <inheritdoc/>
    public IReadOnlyList<(long Id, string Record, bool Final)> Records(long ladder)
    {
        using var c = Open();
        return All(c, null, "SELECT id, record, final FROM matches WHERE ladder_id = @l AND state = @d ORDER BY id",
            r => (r.GetInt64(0), r.GetString(1), Flag(r, 2)), ("l", ladder), ("d", MatchRow.Done));
    }

    /// <inheritdoc/>
    public IReadOnlyDictionary<long, int> Games(long ladder)
    {
        using var c = Open();
        var games = new Dictionary<long, int>();
        foreach (var (team, count) in All(c, null,
            "SELECT team, COUNT(*) FROM (SELECT team_a AS team FROM matches WHERE ladder_id = @l UNION ALL SELECT team_b AS team FROM matches WHERE ladder_id = @l) AS sides GROUP BY team",
            r => (r.GetInt64(0), Convert.ToInt32(r.GetValue(1), CultureInfo.InvariantCulture)), ("l", ladder)))
        {
            games[team] = count;
        }

        return games;
    }

    /// <inheritdoc/>
    public bool StartFinal(long ladder, IReadOnlyList<(long TeamA, long TeamB, long SubA, long SubB)> matches, Func<long, ulong> seedOf)
    {
        using var c = Open();
        using var t = c.BeginTransaction();
        if (Convert.ToInt64(Scalar(c, t, "SELECT COUNT(*) FROM matches WHERE ladder_id = @l AND final = 1", ("l", ladder)), CultureInfo.InvariantCulture) > 0)
        {
            return false;
        }

        Execute(c, t, "DELETE FROM matches WHERE ladder_id = @l AND state = @q AND final = 0", ("l", ladder), ("q", MatchRow.Queued));
        foreach (var (teamA, teamB, subA, subB) in matches)
        {
            long id = Convert.ToInt64(Scalar(c, t,
                "INSERT INTO matches (ladder_id, seed, team_a, team_b, sub_a, sub_b, state, created, final) VALUES (@l, 0, @ta, @tb, @sa, @sb, @s, @c, 1) RETURNING id",
                ("l", ladder), ("ta", teamA), ("tb", teamB), ("sa", subA), ("sb", subB), ("s", MatchRow.Queued), ("c", Now())), CultureInfo.InvariantCulture);
            Execute(c, t, "UPDATE matches SET seed = @s WHERE id = @id", ("s", unchecked((long)seedOf(id))), ("id", id));
        }

        t.Commit();
        return true;
    }

    /// <inheritdoc/>
    public IReadOnlyList<MatchRow> FinalMatches(long ladder)
    {
        using var c = Open();
        return All(c, null, MatchSelect + " WHERE ladder_id = @l AND final = 1 ORDER BY id", ReadMatch, ("l", ladder));
    }

    /// <inheritdoc/>
    public void Dispose() => _owned?.Dispose();

    private DbConnection Open()
    {
        var c = _connect();
        c.Open();
        _dialect.Opened(c);
        return c;
    }

    private static string Now() => Time(DateTime.UtcNow);

    private static string Time(DateTime t) => t.ToUniversalTime().ToString("yyyy-MM-dd'T'HH:mm:ss.fffffff'Z'", CultureInfo.InvariantCulture);

    private static DateTime ParseTime(string s) => DateTime.Parse(s, CultureInfo.InvariantCulture, DateTimeStyles.AdjustToUniversal | DateTimeStyles.AssumeUniversal);

    // A 0/1 column (INTEGER: 64 bits in SQLite, 32 in PostgreSQL).
    private static bool Flag(DbDataReader r, int column) => Convert.ToInt64(r.GetValue(column), CultureInfo.InvariantCulture) != 0;

    private static LadderRow ReadLadder(DbDataReader r) =>
        new(r.GetInt64(0), r.GetString(1), Convert.ToInt32(r.GetValue(2), CultureInfo.InvariantCulture), unchecked((ulong)r.GetInt64(3)), Flag(r, 4), ParseTime(r.GetString(5)));

    private static TeamRow ReadTeam(DbDataReader r) =>
        new(r.GetInt64(0), r.GetString(1), r.GetString(2), r.IsDBNull(3) ? null : r.GetString(3), r.IsDBNull(4) ? null : r.GetString(4), ParseTime(r.GetString(5)), r.IsDBNull(6) ? 0 : r.GetInt64(6));

    private static SubmissionRow ReadSubmission(DbDataReader r) =>
        new(r.GetInt64(0), r.GetInt64(1), ParseTime(r.GetString(2)), r.GetString(3), r.GetString(4), r.GetString(5), r.GetString(6), r.IsDBNull(7) ? 0 : r.GetInt64(7));

    private static MatchRow ReadMatch(DbDataReader r) =>
        new(r.GetInt64(0), r.GetInt64(1), unchecked((ulong)r.GetInt64(2)), [r.GetInt64(3), r.GetInt64(4)], [r.GetInt64(5), r.GetInt64(6)], r.GetString(7),
            ParseTime(r.GetString(8)), r.IsDBNull(9) ? null : ParseTime(r.GetString(9)), r.IsDBNull(10) ? null : ParseTime(r.GetString(10)),
            r.IsDBNull(11) ? null : r.GetString(11), Flag(r, 12));

    private static DbCommand Command(DbConnection c, DbTransaction? t, string sql, (string Name, object? Value)[] parameters)
    {
        var command = c.CreateCommand();
        command.CommandText = sql;
        command.Transaction = t;
        foreach (var (name, value) in parameters)
        {
            var p = command.CreateParameter();
            p.ParameterName = "@" + name;
            p.Value = value ?? DBNull.Value;
            command.Parameters.Add(p);
        }

        return command;
    }

    private static int Execute(DbConnection c, DbTransaction? t, string sql, params (string Name, object? Value)[] parameters)
    {
        using var command = Command(c, t, sql, parameters);
        return command.ExecuteNonQuery();
    }

    private static object? Scalar(DbConnection c, DbTransaction? t, string sql, params (string Name, object? Value)[] parameters)
    {
        using var command = Command(c, t, sql, parameters);
        var value = command.ExecuteScalar();
        return value is DBNull ? null : value;
    }

    private static T? One<T>(DbConnection c, DbTransaction? t, string sql, Func<DbDataReader, T> read, params (string Name, object? Value)[] parameters)
    {
        using var command = Command(c, t, sql, parameters);
        using var reader = command.ExecuteReader(CommandBehavior.SingleRow);
        return reader.Read() ? read(reader) : default;
    }

    private static List<T> All<T>(DbConnection c, DbTransaction? t, string sql, Func<DbDataReader, T> read, params (string Name, object? Value)[] parameters)
    {
        using var command = Command(c, t, sql, parameters);
        using var reader = command.ExecuteReader();
        var list = new List<T>();
        while (reader.Read())
        {
            list.Add(read(reader));
        }

        return list;
    }
}
