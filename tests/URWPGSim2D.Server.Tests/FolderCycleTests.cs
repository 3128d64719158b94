using System.Text.RegularExpressions;
using Mono.Cecil;
using Mono.Cecil.Cil;

namespace URWPGSim2D.Server.Tests;

/// <summary>
/// The folders of every product project depend on each other one way: no folder uses a folder that
/// uses it back, directly or round a longer loop. A type belongs to the folder its source file is in,
/// and a folder's namespace is its path (checked on every source file, save the folders whose
/// namespace is a contract: the original's in the compatibility layer, the SDK's sensing in the
/// SDK's namespace). What a folder uses is read from the compiled assembly: every type named in a
/// signature, field, local, base type, or instruction of a type declared there.
/// </summary>
public sealed partial class FolderCycleTests
{
    // Public types users know by a namespace other than their folder's: the type belongs to the folder
    // its source file is in. The collision detector is the narrow phase's public face; the query world
    // and its answers are a view of the motion world, which itself answers queries with shape queries.
    private static readonly Dictionary<string, string> FiledElsewhere = new(StringComparer.Ordinal)
    {
        ["URWPGSim2D.Collision.CollisionDetector"] = "NarrowPhase",
        ["URWPGSim2D.Collision.Queries.QueryWorld"] = "Motion",
        ["URWPGSim2D.Collision.Queries.BodyRayHit"] = "Motion",
        ["URWPGSim2D.Collision.Queries.BodyDistance"] = "Motion",
    };

    // Folders whose namespace is not their path because users' code names it: project and folder → namespace.
    private static readonly Dictionary<(string Project, string Folder), string> ContractNamespaces = new()
    {
        [("URWPGSim2D.Strategies", "Sensing")] = "URWPGSim2D.Strategies",
        [("URWPGSim2D.Compat", "Common")] = "URWPGSim2D.Common",
        [("URWPGSim2D.Compat", "Core")] = "URWPGSim2D.Core",
        [("URWPGSim2D.Compat", "StrategyHelper")] = "URWPGSim2D.StrategyHelper",
        [("URWPGSim2D.Compat", "StrategyLoader")] = "URWPGSim2D.StrategyLoader",
        [("URWPGSim2D.Compat", "Xna")] = "Microsoft.Xna.Framework",
    };

    [Theory]
    [InlineData("URWPGSim2D.Engine", 120)]
    [InlineData("URWPGSim2D.Hosting", 45)]
    [InlineData("URWPGSim2D.Viewer", 10)]
    [InlineData("URWPGSim2D.Tournament", 40)]
    [InlineData("URWPGSim2D.Server", 80)]
    [InlineData("URWPGSim2D.Collision", 100)]
    [InlineData("URWPGSim2D.Ladder", 15)]
    [InlineData("URWPGSim2D.Strategies", 20)]
    [InlineData("URWPGSim2D.Compat", 40)]
    [InlineData("URWPGSim2D.Protocol", 10)]
    [InlineData("URWPGSim2D.Learning", 1)]
    public void EveryFilesNamespaceIsItsFolder(string project, int atLeast)
    {
        var wrong = new List<string>();
        int files = 0;
        foreach (var (relative, text) in SourceFiles(project))
        {
            files++;
            if (!TypeDeclaration().IsMatch(text))
            {
                continue; // assembly attributes only
            }

            string folder = Path.GetDirectoryName(relative) ?? string.Empty;
            string expected = ContractNamespaces.TryGetValue((project, folder), out string? contract) ? contract
                : folder.Length == 0 ? project : project + "." + folder.Replace(Path.DirectorySeparatorChar, '.');
            string? actual = Namespace().Match(text) is { Success: true } m ? m.Groups[1].Value : null;
            if (FiledElsewhere.Any(kv => kv.Key == actual + "." + Path.GetFileName(relative).Split('.')[0] && kv.Value == folder))
            {
                continue;
            }

            if (actual != expected)
            {
                wrong.Add($"{relative}: namespace {actual ?? "(none)"}, folder {expected}");
            }
        }

        Assert.True(files > atLeast, $"only {files} source files seen");
        Assert.Empty(wrong);
    }

    [Theory]
    [InlineData("URWPGSim2D.Engine", "Matches", "Simulation")]
    [InlineData("URWPGSim2D.Tournament", "", "Batch")]
    [InlineData("URWPGSim2D.Server", "Cli", "Json")]
    [InlineData("URWPGSim2D.Collision", "Motion", "Shapes")]
    [InlineData("URWPGSim2D.Ladder", "", "Storage")]
    [InlineData("URWPGSim2D.Strategies", "Sensing", "")]
    [InlineData("URWPGSim2D.Compat", "Adapter", "Common")]
    public void NoFolderDependsOnItselfRoundALoop(string project, string user, string used)
    {
        var uses = FolderUses(System.Reflection.Assembly.Load(project).Location, SourceFolders(project));
        Assert.Contains(used, uses[user]); // the scan sees uses
        var loops = Loops(uses.ToDictionary(kv => kv.Key, kv => (IReadOnlyCollection<string>)kv.Value.Keys));
        Assert.True(loops.Count == 0, "folder loops:\n" + string.Join("\n", loops.Select(loop =>
            string.Join(", ", loop.SelectMany(a => loop.Where(b => uses[a].ContainsKey(b)).Select(b => $"{a} -> {b} ({uses[a][b]})"))))));
    }

    [Fact]
    public void TheLoopFinderFindsLoops()
    {
        var graph = new Dictionary<string, IReadOnlyCollection<string>>
        {
            ["a"] = ["b"], ["b"] = ["c"], ["c"] = ["a", "d"], ["d"] = [], ["e"] = ["e"], ["f"] = ["d"],
        };
        var loops = Loops(graph);
        Assert.Equal(2, loops.Count);
        Assert.Contains(loops, l => l.SetEquals(["a", "b", "c"]));
        Assert.Contains(loops, l => l.SetEquals(["e"]));
        Assert.Empty(Loops(new Dictionary<string, IReadOnlyCollection<string>> { ["a"] = ["b"], ["b"] = [] }));
    }

    // For each folder (namespace below the root, "" for the root), the folders its types use, each with one type pair as evidence.
    private static Dictionary<string, Dictionary<string, string>> FolderUses(string assemblyPath, IReadOnlyDictionary<string, string> root)
    {
        using var assembly = AssemblyDefinition.ReadAssembly(assemblyPath);
        var uses = new Dictionary<string, Dictionary<string, string>>(StringComparer.Ordinal);
        foreach (var type in assembly.MainModule.GetTypes())
        {
            string? from = Folder(type, root);
            if (from is null)
            {
                continue;
            }

            if (!uses.TryGetValue(from, out var set))
            {
                uses[from] = set = new Dictionary<string, string>(StringComparer.Ordinal);
            }

            void Use(TypeReference? to)
            {
                switch (to)
                {
                    case null or GenericParameter:
                        return;
                    case GenericInstanceType g:
                        foreach (var a in g.GenericArguments)
                        {
                            Use(a);
                        }

                        Use(g.ElementType);
                        return;
                    case TypeSpecification s:
                        Use(s.ElementType);
                        return;
                }

                if (Folder(to, root) is { } target && target != from && !set.ContainsKey(target))
                {
                    set[target] = $"{Outer(type).Name} uses {Outer(to).Name}";
                }
            }

            Use(type.BaseType);
            foreach (var i in type.Interfaces)
            {
                Use(i.InterfaceType);
            }

            foreach (var f in type.Fields)
            {
                Use(f.FieldType);
            }

            foreach (var p in type.Properties)
            {
                Use(p.PropertyType);
            }

            foreach (var m in type.Methods)
            {
                Use(m.ReturnType);
                foreach (var p in m.Parameters)
                {
                    Use(p.ParameterType);
                }

                if (!m.HasBody)
                {
                    continue;
                }

                foreach (var v in m.Body.Variables)
                {
                    Use(v.VariableType);
                }

                foreach (var instruction in m.Body.Instructions)
                {
                    switch (instruction.Operand)
                    {
                        case TypeReference t:
                            Use(t);
                            break;
                        case MethodReference r:
                            Use(r.DeclaringType);
                            Use(r.ReturnType);
                            foreach (var p in r.Parameters)
                            {
                                Use(p.ParameterType);
                            }

                            break;
                        case FieldReference r:
                            Use(r.DeclaringType);
                            Use(r.FieldType);
                            break;
                    }
                }
            }
        }

        foreach (var targets in uses.Values.SelectMany(s => s.Keys).ToList())
        {
            uses.TryAdd(targets, new Dictionary<string, string>(StringComparer.Ordinal));
        }

        return uses;
    }

    private static TypeReference Outer(TypeReference t)
    {
        while (t.IsNested)
        {
            t = t.DeclaringType;
        }

        return t;
    }

    // The folder of a type of the project: where the source file that declares it is (null for a type from elsewhere or made by the compiler).
    private static string? Folder(TypeReference t, IReadOnlyDictionary<string, string> root)
    {
        string name = Outer(t).FullName;
        int arity = name.IndexOf('`', StringComparison.Ordinal);
        return root.TryGetValue(arity < 0 ? name : name[..arity], out string? folder) ? folder : null;
    }

    // The project's C# sources (not the build's outputs under obj/ and bin/): each path below the project and its text.
    private static IEnumerable<(string Relative, string Text)> SourceFiles(string project)
    {
        string source = Repository.PathOf("src/" + project);
        foreach (string file in Directory.EnumerateFiles(source, "*.cs", SearchOption.AllDirectories))
        {
            string relative = Path.GetRelativePath(source, file);
            if (!relative.StartsWith("obj" + Path.DirectorySeparatorChar, StringComparison.Ordinal) && !relative.StartsWith("bin" + Path.DirectorySeparatorChar, StringComparison.Ordinal))
            {
                yield return (relative, File.ReadAllText(file));
            }
        }
    }

    // Every top-level type the project's sources declare (namespace and name) and the folder of its file.
    private static Dictionary<string, string> SourceFolders(string project)
    {
        var folders = new Dictionary<string, string>(StringComparer.Ordinal);
        foreach (var (relative, text) in SourceFiles(project))
        {
            string ns = Namespace().Match(text) is { Success: true } m ? m.Groups[1].Value + "." : string.Empty;
            string folder = (Path.GetDirectoryName(relative) ?? string.Empty).Replace(Path.DirectorySeparatorChar, '.');
            foreach (Match declared in TopLevelTypeName().Matches(text))
            {
                string name = ns + declared.Groups[1].Value;
                Assert.True(!folders.TryGetValue(name, out string? other) || other == folder, $"{name} is declared in two folders: {other} and {folder}");
                folders[name] = FiledElsewhere.TryGetValue(name, out string? filed) ? filed : folder;
            }
        }

        Assert.NotEmpty(folders);
        return folders;
    }

    // The strongly connected sets of more than one folder, or of one that uses itself (Tarjan).
    private static List<HashSet<string>> Loops(IReadOnlyDictionary<string, IReadOnlyCollection<string>> graph)
    {
        var index = new Dictionary<string, int>(StringComparer.Ordinal);
        var low = new Dictionary<string, int>(StringComparer.Ordinal);
        var stack = new Stack<string>();
        var onStack = new HashSet<string>(StringComparer.Ordinal);
        var loops = new List<HashSet<string>>();
        int next = 0;

        void Visit(string v)
        {
            index[v] = low[v] = next++;
            stack.Push(v);
            onStack.Add(v);
            foreach (string w in graph.TryGetValue(v, out var ws) ? ws : [])
            {
                if (!index.ContainsKey(w))
                {
                    Visit(w);
                    low[v] = Math.Min(low[v], low[w]);
                }
                else if (onStack.Contains(w))
                {
                    low[v] = Math.Min(low[v], index[w]);
                }
            }

            if (low[v] == index[v])
            {
                var component = new HashSet<string>(StringComparer.Ordinal);
                string w;
                do
                {
                    w = stack.Pop();
                    onStack.Remove(w);
                    component.Add(w);
                }
                while (w != v);
                if (component.Count > 1 || (graph.TryGetValue(v, out var self) && self.Contains(v)))
                {
                    loops.Add(component);
                }
            }
        }

        foreach (string v in graph.Keys)
        {
            if (!index.ContainsKey(v))
            {
                Visit(v);
            }
        }

        return loops;
    }

    // A type declared at the top of a file-scoped namespace (not indented), its name.
    [GeneratedRegex(@"^(?:(?:public|internal|static|sealed|abstract|readonly|partial|ref|unsafe|file)\s+)*(?:class|struct|record struct|record class|record|interface|enum|delegate\s+[\w.<>\[\],?]+)\s+(\w+)", RegexOptions.Multiline)]
    private static partial Regex TopLevelTypeName();

    [GeneratedRegex(@"^namespace ([\w.]+);", RegexOptions.Multiline)]
    private static partial Regex Namespace();

    [GeneratedRegex(@"^\s*(?:(?:public|internal|private|protected|static|sealed|abstract|readonly|partial|ref|unsafe|file)\s+)*(?:class|struct|record|interface|enum|delegate)\s", RegexOptions.Multiline)]
    private static partial Regex TypeDeclaration();
}
