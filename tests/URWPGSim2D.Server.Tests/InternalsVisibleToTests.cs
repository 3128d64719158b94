using System.Reflection.Metadata;
using System.Reflection.PortableExecutable;
using System.Xml.Linq;

namespace URWPGSim2D.Server.Tests;

/// <summary>
/// The product assemblies (every project under <c>src/</c>) meet only through their public API: none
/// opens its internals to another product assembly (test assemblies and benchmarks may see them).
/// Checked twice: on the project files' <c>InternalsVisibleTo</c> items, and on the
/// <c>InternalsVisibleToAttribute</c>s the built assemblies this test runs with really carry (however
/// they were declared).
/// </summary>
public sealed class InternalsVisibleToTests
{
    // The assemblies the server's tests run with: the server and every library it references.
    private static readonly string[] Referenced =
    [
        "URWPGSim2D.Server", "URWPGSim2D.Collision", "URWPGSim2D.Engine", "URWPGSim2D.Strategies", "URWPGSim2D.Strategy", "URWPGSim2D.Compat",
        "URWPGSim2D.Protocol", "URWPGSim2D.Hosting", "URWPGSim2D.Viewer", "URWPGSim2D.Tournament", "URWPGSim2D.Ladder",
    ];

    [Fact]
    public void NoProjectFileOpensItsInternalsToAnotherProduct()
    {
        var products = ProductAssemblies();
        Assert.Superset(Referenced.ToHashSet(StringComparer.Ordinal), products.Keys.ToHashSet(StringComparer.Ordinal));
        var grants = new List<string>();
        foreach (var (assembly, project) in products)
        {
            foreach (XElement item in XDocument.Load(project).Descendants("InternalsVisibleTo"))
            {
                string? friend = item.Attribute("Include")?.Value;
                if (friend is not null && products.ContainsKey(friend))
                {
                    grants.Add($"{assembly} -> {friend}");
                }
            }
        }

        Assert.Empty(grants);
    }

    [Fact]
    public void NoBuiltProductAssemblyOpensItsInternalsToAnotherProduct()
    {
        var products = ProductAssemblies();
        var grants = new List<string>();
        int read = 0;
        foreach (string assembly in products.Keys)
        {
            string file = Path.Combine(AppContext.BaseDirectory, assembly + ".dll");
            if (!File.Exists(file))
            {
                Assert.DoesNotContain(assembly, Referenced); // only a library the server does not use may be absent
                continue;
            }

            read++;
            foreach (string friend in FriendsOf(file))
            {
                if (products.ContainsKey(friend))
                {
                    grants.Add($"{assembly} -> {friend}");
                }
            }
        }

        Assert.Equal(Referenced.Length, read);
        Assert.Empty(grants);
    }

    [Fact]
    public void TheBuiltAssembliesAreReadForTheirFriends()
    {
        // The reader sees the grants that are there: the engine opens its internals to these tests.
        string engine = Path.Combine(AppContext.BaseDirectory, "URWPGSim2D.Engine.dll");
        Assert.Contains("URWPGSim2D.Server.Tests", FriendsOf(engine));
    }

    // Every project under src/: its assembly name (AssemblyName, else the file's name) and its file.
    private static Dictionary<string, string> ProductAssemblies()
    {
        var products = new Dictionary<string, string>(StringComparer.Ordinal);
        foreach (string project in Directory.EnumerateFiles(Repository.PathOf("src"), "*.csproj", SearchOption.AllDirectories))
        {
            string name = XDocument.Load(project).Descendants("AssemblyName").Select(e => e.Value.Trim()).FirstOrDefault()
                ?? Path.GetFileNameWithoutExtension(project);
            products.Add(name, project);
        }

        return products;
    }

    // The simple names the assembly's InternalsVisibleToAttributes name.
    private static List<string> FriendsOf(string file)
    {
        using var stream = File.OpenRead(file);
        using var pe = new PEReader(stream);
        MetadataReader metadata = pe.GetMetadataReader();
        var friends = new List<string>();
        foreach (CustomAttributeHandle handle in metadata.GetAssemblyDefinition().GetCustomAttributes())
        {
            CustomAttribute attribute = metadata.GetCustomAttribute(handle);
            if (attribute.Constructor.Kind != HandleKind.MemberReference)
            {
                continue;
            }

            var constructor = metadata.GetMemberReference((MemberReferenceHandle)attribute.Constructor);
            if (constructor.Parent.Kind != HandleKind.TypeReference
                || metadata.GetString(metadata.GetTypeReference((TypeReferenceHandle)constructor.Parent).Name) != "InternalsVisibleToAttribute")
            {
                continue;
            }

            BlobReader value = metadata.GetBlobReader(attribute.Value);
            value.ReadUInt16(); // the prolog
            string friend = value.ReadSerializedString() ?? string.Empty;
            friends.Add(friend.Split(',')[0].Trim());
        }

        return friends;
    }
}
