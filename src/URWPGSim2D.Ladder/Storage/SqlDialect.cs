using System;
using System.Collections.Generic;
using System.Data.Common;
using Microsoft.Data.Sqlite;

namespace URWPGSim2D.Ladder.Storage;

/// <summary>What differs between the databases: the schema's migrations (in order; each a list of statements), how the next queued match is found, and what a fresh connection is told.</summary>
internal sealed class SqlDialect
{
    private SqlDialect(string name, IReadOnlyList<string[]> migrations, string nextQueued, Action<DbConnection> opened)
    {
        Name = name;
        Migrations = migrations;
        NextQueued = nextQueued;
        Opened = opened;
    }

    /// <summary>The database's name.</summary>
    public string Name { get; }

    /// <summary>Migration N (0-based) brings the schema from version N to N + 1.</summary>
    public IReadOnlyList<string[]> Migrations { get; }

    /// <summary>The id of the next queued match of ladder @l (final round first, then oldest); @q is the queued state.</summary>
    public string NextQueued { get; }

    /// <summary>Run on each opened connection.</summary>
    public Action<DbConnection> Opened { get; }

    private static string[] Schema1(string id) =>
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
    ];

    /// <summary>SQLite: write-ahead log, a busy wait instead of an error when another connection writes.</summary>
    public static SqlDialect Sqlite { get; } = new(
        "sqlite",
        [Schema1("INTEGER PRIMARY KEY")],
        "SELECT id FROM matches WHERE ladder_id = @l AND state = @q ORDER BY final DESC, id LIMIT 1",
        c =>
        {
            using var command = c.CreateCommand();
            command.CommandText = "PRAGMA journal_mode = WAL; PRAGMA busy_timeout = 30000; PRAGMA foreign_keys = ON; PRAGMA synchronous = FULL;";
            command.ExecuteNonQuery();
        });

    /// <summary>A store in the SQLite file <paramref name="path"/>.</summary>
    public static SqlLadderStore SqliteStore(string path)
    {
        string connection = new SqliteConnectionStringBuilder { DataSource = path, Pooling = true }.ToString();
        return new SqlLadderStore(() => new SqliteConnection(connection), Sqlite);
    }
}
