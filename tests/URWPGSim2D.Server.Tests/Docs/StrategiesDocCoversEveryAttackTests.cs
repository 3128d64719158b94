using System.Reflection;

namespace URWPGSim2D.Server.Tests.Docs;

/// <summary>
/// docs/strategies.md's fault, sandbox and per-platform tables against the tests of hostile
/// strategies: every attack a test plays names the row that tells users what it gets (and that row
/// exists), every row of the fault and sandbox tables is backed by at least one such test, and every
/// test in the classes of attacks is marked, so a new attack cannot land without its row.
/// </summary>
public sealed class StrategiesDocCoversEveryAttackTests
{
    // The test classes whose tests play attacks, and their tests that do not (with why).
    private static readonly Type[] AttackClasses =
    [
        typeof(HostileCompileTests), typeof(HostileOriginalApiTests), typeof(HostileStrategyTests), typeof(HostileTextTests),
        typeof(SandboxLimitTests), typeof(HostTimeTests), typeof(RunFolderTests), typeof(HostProtocolFaultTests),
        typeof(Tournament.TournamentHostileTests),
    ];

    private static readonly Dictionary<string, string> NotAttacks = new(StringComparer.Ordinal)
    {
        [nameof(HostileCompileTests.Compile_errors_from_the_compilers_process_read_as_the_in_process_compiler_words_them)] = "the wording of honest compile errors",
        [nameof(SandboxLimitTests.A_bad_limit_is_refused_with_one_line)] = "the organiser's bad option values",
    };

    private static readonly Dictionary<string, string> TableHeaders = new(StringComparer.Ordinal)
    {
        ["faults"] = "| fault | counted as | the team's fish |",
        ["sandbox"] = "| the host | sees / may do |",
        ["platforms"] = "| platform |",
    };

    [Fact]
    public void Every_attack_names_a_row_and_every_fault_and_sandbox_row_is_backed_by_an_attack()
    {
        var tables = Tables();
        var claimed = tables.ToDictionary(t => t.Key, _ => new HashSet<string>(StringComparer.Ordinal));
        var problems = new List<string>();
        foreach (var (method, attack) in Attacks())
        {
            if (!tables.TryGetValue(attack.Table, out var rows))
            {
                problems.Add($"{method}: no table '{attack.Table}'");
                continue;
            }

            var matches = rows.Where(r => r.Contains(attack.Row, StringComparison.Ordinal)).ToList();
            if (matches.Count != 1)
            {
                problems.Add($"{method}: {matches.Count} rows of the {attack.Table} table start with words '{attack.Row}'");
                continue;
            }

            claimed[attack.Table].Add(matches[0]);
        }

        foreach (string table in new[] { "faults", "sandbox" })
        {
            problems.AddRange(tables[table].Where(row => !claimed[table].Contains(row)).Select(row => $"the {table} table's row '{row}' has no test that plays it"));
        }

        Assert.True(problems.Count == 0, string.Join("\n", problems));
    }

    [Fact]
    public void Every_test_of_the_attack_classes_is_marked_with_its_row()
    {
        var unmarked = AttackClasses
            .SelectMany(type => type.GetMethods(BindingFlags.Public | BindingFlags.Instance | BindingFlags.DeclaredOnly))
            .Where(m => m.GetCustomAttributes<FactAttribute>().Any() && !m.GetCustomAttributes<AttackAttribute>().Any() && !NotAttacks.ContainsKey(m.Name))
            .Select(m => $"{m.DeclaringType!.Name}.{m.Name}")
            .ToList();
        Assert.True(unmarked.Count == 0, "tests of attacks without [Attack(table, row)]:\n" + string.Join("\n", unmarked));
        Assert.True(Attacks().Count() >= 50, "the attack tests were not found"); // guards the reflection itself
    }

    [Fact]
    public void The_tables_are_found_with_their_rows()
    {
        var tables = Tables();
        Assert.Equal(["faults", "platforms", "sandbox"], tables.Keys.Order(StringComparer.Ordinal));
        Assert.Contains("its host ends: stack overflow, `Environment.Exit`, `Environment.FailFast`, a native crash, the host killed, the CPU-time limit below (`strategy host ended: out of CPU time: it reached its limit of N s of CPU time for the match (SIGXCPU), killed`), a constructor or static constructor of the strategy class that throws (the host cannot create it), its sandbox out of memory (heap, native memory and its RAM-backed files together past the sandbox's limit: `strategy host ended: out of memory: its sandbox reached its limit of N MiB, killed`)", tables["faults"]);
        Assert.Equal(["files", "disk", "network", "processes", "user", "environment", "memory", "CPU", "core dumps"], tables["sandbox"]);
        Assert.Equal(6, tables["platforms"].Count);
    }

    private static IEnumerable<(string Method, AttackAttribute Attack)> Attacks() =>
        typeof(StrategiesDocCoversEveryAttackTests).Assembly.GetTypes()
            .SelectMany(t => t.GetMethods(BindingFlags.Public | BindingFlags.Instance | BindingFlags.DeclaredOnly))
            .SelectMany(m => m.GetCustomAttributes<AttackAttribute>().Select(a => ($"{m.DeclaringType!.Name}.{m.Name}", a)));

    // Each table's rows as their first cells, found by the table's header line.
    private static Dictionary<string, List<string>> Tables()
    {
        string[] lines = File.ReadAllLines(Repository.PathOf("docs/strategies.md"));
        var tables = new Dictionary<string, List<string>>(StringComparer.Ordinal);
        foreach (var (name, header) in TableHeaders)
        {
            int at = Array.FindIndex(lines, l => l.StartsWith(header, StringComparison.Ordinal));
            Assert.True(at >= 0, $"docs/strategies.md has no table starting '{header}'");
            tables[name] = lines.Skip(at + 2).TakeWhile(l => l.StartsWith('|')).Select(l => l.Split(" | ")[0].TrimStart('|', ' ')).ToList();
        }

        return tables;
    }
}
