using System;
using System.Data.Common;
using System.IO;
using URWPGSim2D.Ladder.Storage;

namespace URWPGSim2D.Ladder;

/// <summary>Opens the ladder's store: SQLite in the data folder, or the PostgreSQL database <c>--database</c> names.</summary>
internal static class LadderDatabase
{
    /// <summary>The store, its schema brought up to date.</summary>
    /// <exception cref="LadderInputException">The connection string is not one, or the database cannot be reached or migrated (the message says why).</exception>
    public static ILadderStore Open(LadderSettings settings)
    {
        if (settings.Database is null)
        {
            return SqlDialect.SqliteStore(Path.Combine(settings.DataDir, "ladder.db"));
        }

        SqlLadderStore store;
        try
        {
            store = SqlDialect.PostgreSqlStore(settings.Database);
        }
        catch (ArgumentException e)
        {
            throw new LadderInputException("--database: not a PostgreSQL connection string (Host=…;Database=…): " + e.Message.ReplaceLineEndings(" "));
        }

        try
        {
            store.Migrate();
        }
        catch (Exception e) when (e is DbException or TimeoutException or IOException or System.Net.Sockets.SocketException)
        {
            store.Dispose();
            throw new LadderInputException("--database: cannot use the PostgreSQL database: " + e.Message.ReplaceLineEndings(" "));
        }

        return store;
    }
}
