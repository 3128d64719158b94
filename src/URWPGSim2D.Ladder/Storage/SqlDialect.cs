using System;
using System.Collections.Generic;
using System.Data.Common;
using Microsoft.Data.Sqlite;
using Npgsql;

namespace URWPGSim2D.Ladder.Storage;

/// <summary>
/// What differs between the databases: the types of an id column and of bytes in the schema's migrations (the
/// statements themselves are the same for SQLite and PostgreSQL), how the next queued match is found
/// and locked, how concurrent migrations wait for each other, and what a fresh connection is told.
/// </summary>
internal sealed class SqlDialect
{
    private SqlDialect(string name, string id, string blob, string nextQueued, string? migrationLock, Action<DbConnection> opened)
    {
        Name = name;
        Migrations = Schema(id, blob);
        NextQueued = nextQueued;
        MigrationLock = migrationLock;
        Opened = opened;
    }

    /// <summary>The database's name.</summary>
    public string Name { get; }

    /// <summary>Migration N (0-based) brings the schema from version N to N + 1.</summary>
    public IReadOnlyList<string[]> Migrations { get; }

    /// <summary>The id of the next queued match of ladder @l (final round first, then oldest); @q is the queued state.</summary>
    public string NextQueued { get; }

    /// <summary>Run first in the migrations' transaction so that two processes starting at once migrate one after the other (null: the transaction itself serialises them).</summary>
    public string? MigrationLock { get; }

    /// <summary>Run on each opened connection.</summary>
    public Action<DbConnection> Opened { get; }

    // The migrations, in order, written once for both databases: {id} is the dialect's id column, {blob} its type of bytes.
    private static List<string[]> Schema(string id, string blob) =>
    [
        [
            "CREATE TABLE settings (key TEXT PRIMARY KEY, value TEXT NOT NULL)",
            $"CREATE TABLE ladders (id {id}, item TEXT NOT NULL, cycles INTEGER NOT NULL, first_seed BIGINT NOT NULL, paused INTEGER NOT NULL, created TEXT NOT NULL)",
            $"CREATE TABLE teams (id {id}, name TEXT NOT NULL UNIQUE, token_hash TEXT NOT NULL UNIQUE, password_hash TEXT NULL, house TEXT NULL, created TEXT NOT NULL)",
            $"CREATE TABLE submissions (id {id}, team_id BIGINT NOT NULL REFERENCES teams (id), created TEXT NOT NULL, kind TEXT NOT NULL, path TEXT NOT NULL, state TEXT NOT NULL, log TEXT NOT NULL)",
            "CREATE INDEX submissions_team ON submissions (team_id, id)",
            $"CREATE TABLE matches (id {id}, ladder_id BIGINT NOT NULL REFERENCES ladders (id), seed BIGINT NOT NULL, team_a BIGINT NOT NULL, team_b BIGINT NOT NULL, "
                + "sub_a BIGINT NOT NULL, sub_b BIGINT NOT NULL, state TEXT NOT NULL, created TEXT NOT NULL, started TEXT NULL, finished TEXT NULL, record TEXT NULL, final INTEGER NOT NULL)",
            "CREATE INDEX matches_state ON matches (ladder_id, state, id)",
            "CREATE TABLE sessions (token_hash TEXT PRIMARY KEY, team_id BIGINT NOT NULL REFERENCES teams (id), created TEXT NOT NULL)",
        ],
        [
            // The job (Hangfire's id) a match is queued as or claimed by, when worker processes share the database.
            "ALTER TABLE matches ADD COLUMN job TEXT NULL",
        ],
        [
            // Files in the database, so that a worker needs no folder of the service's: each submission's upload, each match's
            // outputs (replay page, strategies' logs), gzip-compressed, with the SHA-256 of their bytes. A data folder of an
            // older version is read into them on the service's start (LadderFiles.Import).
            $"CREATE TABLE submission_files (submission_id BIGINT NOT NULL REFERENCES submissions (id), name TEXT NOT NULL, sha256 TEXT NOT NULL, bytes {blob} NOT NULL, PRIMARY KEY (submission_id, name))",
            $"CREATE TABLE match_files (match_id BIGINT NOT NULL REFERENCES matches (id), name TEXT NOT NULL, sha256 TEXT NOT NULL, bytes {blob} NOT NULL, PRIMARY KEY (match_id, name))",
        ],
        [
            // Several ladders: a submission is for one ladder (a strategy is item-specific), a house entrant plays in one.
            // Rows of before: a submission's ladder is the one it played in, else the newest ladder made before it (the
            // one the service ran then); a house entrant's likewise.
            "ALTER TABLE submissions ADD COLUMN ladder_id BIGINT NULL REFERENCES ladders (id)",
            "UPDATE submissions SET ladder_id = COALESCE((SELECT MIN(m.ladder_id) FROM matches m WHERE m.sub_a = submissions.id OR m.sub_b = submissions.id), "
                + "(SELECT MAX(l.id) FROM ladders l WHERE l.created <= submissions.created), (SELECT MIN(l.id) FROM ladders l))",
            "ALTER TABLE teams ADD COLUMN ladder_id BIGINT NULL REFERENCES ladders (id)",
            "UPDATE teams SET ladder_id = COALESCE((SELECT MIN(m.ladder_id) FROM matches m WHERE m.team_a = teams.id OR m.team_b = teams.id), "
                + "(SELECT MAX(l.id) FROM ladders l WHERE l.created <= teams.created), (SELECT MIN(l.id) FROM ladders l)) WHERE house IS NOT NULL",
            "CREATE INDEX submissions_ladder ON submissions (ladder_id, team_id, id)",
        ],
    ];

    /// <summary>SQLite: write-ahead log, a busy wait instead of an error when another connection writes.</summary>
    public static SqlDialect Sqlite { get; } = new(
        "sqlite",
        "INTEGER PRIMARY KEY",
        "BLOB",
        "SELECT id FROM matches WHERE ladder_id = @l AND state = @q ORDER BY final DESC, id LIMIT 1",
        null,
        c =>
        {
            using var command = c.CreateCommand();
            command.CommandText = "PRAGMA journal_mode = WAL; PRAGMA busy_timeout = 30000; PRAGMA foreign_keys = ON; PRAGMA synchronous = FULL;";
            command.ExecuteNonQuery();
        });

    /// <summary>
    /// PostgreSQL: ids from an identity column; the next queued match locked for the claiming
    /// transaction and skipped by every other (two processes never claim the same one); the
    /// migrations under a transaction-scoped advisory lock.
    /// </summary>
    public static SqlDialect PostgreSql { get; } = new(
        "postgresql",
        "BIGINT GENERATED BY DEFAULT AS IDENTITY PRIMARY KEY",
        "BYTEA",
        "SELECT id FROM matches WHERE ladder_id = @l AND state = @q ORDER BY final DESC, id LIMIT 1 FOR UPDATE SKIP LOCKED",
        "SELECT pg_advisory_xact_lock(4242020001)",
        _ => { });

    /// <summary>A store in the SQLite file <paramref name="path"/>.</summary>
    public static SqlLadderStore SqliteStore(string path)
    {
        string connection = new SqliteConnectionStringBuilder { DataSource = path, Pooling = true }.ToString();
        return new SqlLadderStore(() => new SqliteConnection(connection), Sqlite);
    }

    /// <summary>A store in the PostgreSQL database <paramref name="connection"/> names (<c>Host=…;Database=…</c>).</summary>
    /// <exception cref="ArgumentException">The connection string is not one.</exception>
    public static SqlLadderStore PostgreSqlStore(string connection)
    {
        var source = NpgsqlDataSource.Create(connection);
        return new SqlLadderStore(source.CreateConnection, PostgreSql, source);
    }
}
