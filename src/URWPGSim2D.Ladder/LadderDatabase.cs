using System.IO;
using URWPGSim2D.Ladder.Storage;

namespace URWPGSim2D.Ladder;

/// <summary>Opens the ladder's store: SQLite in the data folder, or the database <c>--database</c> names.</summary>
internal static class LadderDatabase
{
    public static ILadderStore Open(LadderSettings settings)
    {
        if (settings.Database is null)
        {
            return SqlDialect.SqliteStore(Path.Combine(settings.DataDir, "ladder.db"));
        }

        throw new LadderInputException("--database: PostgreSQL is not available in this build; leave --database out for SQLite in --data");
    }
}
