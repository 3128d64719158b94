using System.Diagnostics;
using System.Threading;
using Npgsql;

namespace URWPGSim2D.Ladder.Tests;

/// <summary>
/// A real PostgreSQL server of the tests' own (installed by <c>.ci/install-postgresql</c>): a new
/// cluster in a temporary folder (initdb), started by pg_ctl on a Unix socket in that folder (no TCP
/// port, no system service), stopped by pg_ctl and removed when the tests of the collection end. As
/// root (CI) the cluster's programs run as the user postgres, since initdb refuses root. Each test
/// takes a database of its own (<see cref="NewDatabase"/>).
/// </summary>
public sealed class PostgresServer : IDisposable
{
    private readonly string _bin;
    private readonly string _folder;
    private int _databases;

    public PostgresServer()
    {
        _bin = Directory.Exists("/usr/lib/postgresql")
            ? Directory.GetDirectories("/usr/lib/postgresql").Select(d => Path.Combine(d, "bin"))
                .Where(b => File.Exists(Path.Combine(b, "initdb"))).OrderByDescending(b => int.TryParse(Path.GetFileName(Path.GetDirectoryName(b)), out int v) ? v : 0).FirstOrDefault() ?? string.Empty
            : string.Empty;
        if (_bin.Length == 0)
        {
            throw new InvalidOperationException("PostgreSQL's initdb is not in /usr/lib/postgresql/*/bin: run .ci/install-postgresql (as root)");
        }

        // A folder the cluster's user owns: made by that user (mktemp), so no chown is needed.
        _folder = Run("/usr/bin/mktemp", "-d", "/tmp/urwpg-postgres-XXXXXX").Trim();
        Run(Path.Combine(_bin, "initdb"), "-D", Data, "-U", "postgres", "-A", "trust", "-E", "UTF8", "--no-sync", "--locale=C");
        Run(Path.Combine(_bin, "pg_ctl"), "-D", Data, "-l", Path.Combine(_folder, "server.log"), "-w", "-t", "120",
            "-o", $"-k {_folder} -p 5432 -c listen_addresses='' -c fsync=off -c max_connections=200", "start");
        Admin = new NpgsqlConnectionStringBuilder { Host = _folder, Port = 5432, Username = "postgres", Database = "postgres", Pooling = false }.ToString();
    }

    private string Data => Path.Combine(_folder, "data");

    /// <summary>The connection string of the server's own database (to make others).</summary>
    public string Admin { get; }

    /// <summary>A new empty database; its connection string.</summary>
    public string NewDatabase()
    {
        string name = $"ladder_{Environment.ProcessId}_{Interlocked.Increment(ref _databases)}";
        using (var c = new NpgsqlConnection(Admin))
        {
            c.Open();
            using var command = c.CreateCommand();
            command.CommandText = $"CREATE DATABASE {name}";
            command.ExecuteNonQuery();
        }

        return new NpgsqlConnectionStringBuilder(Admin) { Database = name, Pooling = true }.ToString();
    }

    public void Dispose()
    {
        NpgsqlConnection.ClearAllPools();
        Run(Path.Combine(_bin, "pg_ctl"), "-D", Data, "-m", "immediate", "-w", "stop");
        Run("/bin/rm", "-rf", _folder);
    }

    // A program run to its end, as the user postgres when this process is root; its output, or an error with its output.
    private static string Run(string program, params string[] arguments)
    {
        bool root = Environment.UserName == "root";
        var start = new ProcessStartInfo(root ? "/usr/bin/setpriv" : program) { RedirectStandardOutput = true, RedirectStandardError = true, UseShellExecute = false, WorkingDirectory = "/tmp" };
        if (root)
        {
            foreach (string a in new[] { "--reuid=postgres", "--regid=postgres", "--init-groups", "--", program })
            {
                start.ArgumentList.Add(a);
            }
        }

        foreach (string a in arguments)
        {
            start.ArgumentList.Add(a);
        }

        using var process = Process.Start(start)!;
        var output = process.StandardOutput.ReadToEndAsync();
        string error = process.StandardError.ReadToEnd();
        process.WaitForExit();
        return process.ExitCode == 0 ? output.Result : throw new InvalidOperationException($"{Path.GetFileName(program)} failed ({process.ExitCode}): {error} {output.Result}");
    }
}

/// <summary>The tests that use the PostgreSQL server: one server for all of them, which they use one after another.</summary>
[CollectionDefinition(Name)]
public sealed class PostgresCollection : ICollectionFixture<PostgresServer>
{
    public const string Name = "PostgreSQL";
}
