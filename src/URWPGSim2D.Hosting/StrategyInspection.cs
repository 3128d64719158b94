using System.Collections.Immutable;
using System.Diagnostics.CodeAnalysis;
using System.Reflection;
using System.Reflection.Metadata;
using System.Reflection.Metadata.Ecma335;
using System.Reflection.PortableExecutable;
using URWPGSim2D.Compat.Retargeting;
using URWPGSim2D.Engine.Items.Catalog;
using URWPGSim2D.Engine.Items;

namespace URWPGSim2D.Hosting;

/// <summary>
/// What a strategy DLL is and whether it will load (<c>inspect-dll</c>): read from its metadata, then loaded
/// as <c>run</c> loads it (retargeted when it was built for the original) into a collectible context that is
/// unloaded at once. None of the strategy's code runs: its team name is read from the code of its
/// <c>GetTeamName</c> (or the SDK's <c>TeamName</c>) when that returns a constant string.
/// </summary>
public sealed class StrategyInspection
{
    private const string Justification = "User strategies are loaded at run time from their own files; the server is never trimmed.";

    private StrategyInspection()
    {
    }

    /// <summary>The file, as it was given.</summary>
    public string File { get; private init; } = string.Empty;

    /// <summary>The assembly's name and version.</summary>
    public string Assembly { get; private init; } = string.Empty;

    /// <summary>The SHA-256 of the file's bytes, lower-case hex.</summary>
    public string Sha256 { get; private init; } = string.Empty;

    /// <summary>The framework it was built for.</summary>
    public string Framework { get; private init; } = string.Empty;

    /// <summary>The processor architecture it asks for.</summary>
    public string Architecture { get; private init; } = string.Empty;

    /// <summary>Which strategy API it references: the original's, the SDK's, both or neither.</summary>
    public string Api { get; private init; } = string.Empty;

    /// <summary>Whether it was built for the original (it is retargeted when it loads).</summary>
    public bool Original { get; private init; }

    /// <summary>The name its strategy returns, when its code returns a constant; else null.</summary>
    public string? TeamName { get; private init; }

    /// <summary>The items its code mentions (by a mission variable it reads, or the item's name in a string), with why.</summary>
    public IReadOnlyList<string> Items { get; private init; } = [];

    /// <summary>Each assembly it references, and what stands for it here.</summary>
    public IReadOnlyList<string> References { get; private init; } = [];

    /// <summary>The strategy class <c>run</c> would play, when it loads.</summary>
    public string? StrategyClass { get; private set; }

    /// <summary>Why it will not load (one line), or null when it will.</summary>
    public string? Refusal { get; private set; }

    /// <summary>Every type and member it uses that does not resolve here (all of them, not only the first few).</summary>
    public IReadOnlyList<string> Missing { get; private set; } = [];

    /// <summary>Whether <c>run</c> will load it.</summary>
    public bool Loads => Refusal is null;

    /// <summary>Inspects the assembly at <paramref name="path"/>.</summary>
    /// <param name="path">The DLL's path.</param>
    /// <exception cref="StrategyLoadException">It is not there, cannot be read, or is not a .NET assembly (one line).</exception>
    public static StrategyInspection Of(string path)
    {
        string full;
        byte[] bytes;
        try
        {
            full = Path.GetFullPath(path);
            bytes = System.IO.File.ReadAllBytes(full);
        }
        catch (Exception e) when (e is IOException or UnauthorizedAccessException or ArgumentException or NotSupportedException)
        {
            throw new StrategyLoadException(e is FileNotFoundException or DirectoryNotFoundException ? $"{path}: no such file" : $"{path}: cannot read it: {e.Message}");
        }

        try
        {
            using var pe = new PEReader(ImmutableArray.Create(bytes));
            if (pe.PEHeaders.CorHeader is not { } cor || !pe.HasMetadata)
            {
                throw new StrategyLoadException($"{path}: not a .NET assembly (it has no CLR header)");
            }

            var metadata = pe.GetMetadataReader();
            if (!metadata.IsAssembly)
            {
                throw new StrategyLoadException($"{path}: not a .NET assembly (a module without an assembly manifest)");
            }

            var strings = UserStrings(metadata);
            var inspection = new StrategyInspection
            {
                File = path,
                Assembly = AssemblyName(metadata),
                Sha256 = Convert.ToHexStringLower(System.Security.Cryptography.SHA256.HashData(bytes)),
                Framework = FrameworkOf(metadata),
                Architecture = ArchitectureOf(pe.PEHeaders, cor),
                Api = ApiOf(metadata),
                Original = ReferencesOriginal(metadata),
                TeamName = Hosting.TeamName.Clean(ConstantTeamName(pe, metadata)),
                Items = ItemsMentioned(strings),
                References = ReferencesOf(metadata, Path.GetDirectoryName(full)!),
            };
            inspection.TryLoad(full);
            return inspection;
        }
        catch (BadImageFormatException e)
        {
            throw new StrategyLoadException($"{path}: not a .NET assembly ({e.Message})");
        }
    }

    [UnconditionalSuppressMessage("Trimming", "IL2026", Justification = Justification)]
    private void TryLoad(string full)
    {
        var context = new StrategyLoadContext(full, full);
        try
        {
            System.Reflection.Assembly assembly;
            try
            {
                assembly = OriginalAssemblyLoader.Load(context, full);
            }
            catch (FileLoadException e) when (OriginalAssemblyLoader.Read(full).Retargeted is { } image)
            {
                // The whole list of what is missing, not only the message's first few.
                Refusal = e.Message;
                var loaded = context.LoadFromStream(new MemoryStream(image, writable: false));
                Missing = RetargetedReferenceCheck.Missing(loaded, image).ConvertAll(m => $"{m.Name} ({m.Assembly})");
                return;
            }

            StrategyClass = StrategyResolver.FindType(assembly, Path.GetFileName(full), typeName: null).FullName;
        }
        catch (Exception e) when (e is BadImageFormatException or FileLoadException or IOException or StrategyLoadException)
        {
            Refusal = e.Message;
        }
        finally
        {
            context.Unload();
        }
    }

    private static string AssemblyName(MetadataReader metadata)
    {
        var definition = metadata.GetAssemblyDefinition();
        return $"{metadata.GetString(definition.Name)} {definition.Version}";
    }

    private static string FrameworkOf(MetadataReader metadata)
    {
        foreach (var handle in metadata.GetCustomAttributes(EntityHandle.AssemblyDefinition))
        {
            var attribute = metadata.GetCustomAttribute(handle);
            if (AttributeTypeName(metadata, attribute) == "System.Runtime.Versioning.TargetFrameworkAttribute")
            {
                var value = metadata.GetBlobReader(attribute.Value);
                if (value.ReadUInt16() == 1 && value.ReadSerializedString() is { Length: > 0 } moniker)
                {
                    return $"{moniker} (runtime {metadata.MetadataVersion})";
                }
            }
        }

        return metadata.MetadataVersion switch
        {
            "v2.0.50727" => ".NET Framework 2.0-3.5 (runtime v2.0.50727)",
            "v1.0.3705" or "v1.1.4322" => $".NET Framework 1.x (runtime {metadata.MetadataVersion})",
            "v4.0.30319" => ".NET Framework 4.x or later, or .NET (runtime v4.0.30319, no TargetFramework attribute)",
            string other => $"runtime {other}",
        };
    }

    private static string? AttributeTypeName(MetadataReader metadata, CustomAttribute attribute)
    {
        EntityHandle type = attribute.Constructor.Kind switch
        {
            HandleKind.MemberReference => metadata.GetMemberReference((MemberReferenceHandle)attribute.Constructor).Parent,
            HandleKind.MethodDefinition => metadata.GetMethodDefinition((MethodDefinitionHandle)attribute.Constructor).GetDeclaringType(),
            _ => default,
        };
        return type.Kind switch
        {
            HandleKind.TypeReference => metadata.GetString(metadata.GetTypeReference((TypeReferenceHandle)type).Namespace) + "." + metadata.GetString(metadata.GetTypeReference((TypeReferenceHandle)type).Name),
            HandleKind.TypeDefinition => metadata.GetString(metadata.GetTypeDefinition((TypeDefinitionHandle)type).Namespace) + "." + metadata.GetString(metadata.GetTypeDefinition((TypeDefinitionHandle)type).Name),
            _ => null,
        };
    }

    private static string ArchitectureOf(PEHeaders headers, CorHeader cor)
    {
        bool pe32Plus = headers.PEHeader!.Magic == PEMagic.PE32Plus;
        if ((cor.Flags & CorFlags.Requires32Bit) != 0)
        {
            return "x86 (32-bit required: cleared when it loads, the code is IL)";
        }

        return headers.CoffHeader.Machine switch
        {
            Machine.Amd64 => "x64",
            Machine.Arm64 => "arm64",
            Machine.I386 when !pe32Plus && (cor.Flags & CorFlags.Prefers32Bit) != 0 => "any CPU, 32-bit preferred",
            Machine.I386 when !pe32Plus => "any CPU",
            Machine other => other.ToString().ToLowerInvariant(),
        } + ((cor.Flags & CorFlags.ILOnly) == 0 ? ", with native code" : string.Empty);
    }

    private static string ApiOf(MetadataReader metadata)
    {
        bool original = false, sdk = false;
        foreach (var handle in metadata.TypeReferences)
        {
            var type = metadata.GetTypeReference(handle);
            if (metadata.GetString(type.Name) == "IStrategy")
            {
                string ns = metadata.GetString(type.Namespace);
                original |= ns == "URWPGSim2D.StrategyLoader";
                sdk |= ns == typeof(IStrategy).Namespace;
            }
        }

        return (original, sdk) switch
        {
            (true, true) => "both the original's (URWPGSim2D.StrategyLoader.IStrategy) and the SDK's (IStrategy)",
            (true, false) => "the original's (URWPGSim2D.StrategyLoader.IStrategy)",
            (false, true) => $"the strategy SDK's ({typeof(IStrategy).FullName})",
            _ => "none: it references neither strategy interface",
        };
    }

    private static bool ReferencesOriginal(MetadataReader metadata)
    {
        foreach (var handle in metadata.AssemblyReferences)
        {
            if (OriginalReferences.IsOriginal(metadata.GetString(metadata.GetAssemblyReference(handle).Name)))
            {
                return true;
            }
        }

        return false;
    }

    private static List<string> ReferencesOf(MetadataReader metadata, string folder)
    {
        var list = new List<string>();
        foreach (var handle in metadata.AssemblyReferences)
        {
            var reference = metadata.GetAssemblyReference(handle);
            string name = metadata.GetString(reference.Name);
            string target = OriginalReferences.IsOriginal(name) ? "the compatibility assembly (URWPGSim2D.Compat)"
                : StrategyLoadContext.IsShared(name) ? "shared with the server"
                : RetargetedReferenceCheck.FileOf(name) is not null ? $"this runtime's {name}"
                : System.IO.File.Exists(Path.Combine(folder, name + ".dll")) ? $"{name}.dll beside it"
                : "not found";
            list.Add($"{name} {reference.Version}: {target}");
        }

        return list;
    }

    private static List<string> UserStrings(MetadataReader metadata)
    {
        var strings = new List<string>();
        var handle = MetadataTokens.UserStringHandle(1);
        int size = metadata.GetHeapSize(HeapIndex.UserString);
        while (!handle.IsNil && MetadataTokens.GetHeapOffset(handle) < size)
        {
            strings.Add(metadata.GetUserString(handle));
            handle = metadata.GetNextHandle(handle);
        }

        return strings;
    }

    // The items whose mission variables the code names, or whose name (slug or Chinese) a string contains.
    private static List<string> ItemsMentioned(List<string> strings)
    {
        var mentioned = new List<string>();
        foreach (var item in ItemRegistry.All)
        {
            var why = new List<string>();
            foreach (string key in ItemVariables.Of(item))
            {
                if (strings.Contains(key))
                {
                    why.Add(key);
                }
            }

            string reason = why.Count > 0 ? "reads " + string.Join(", ", why.GetRange(0, Math.Min(3, why.Count))) + (why.Count > 3 ? $" and {why.Count - 3} more" : string.Empty) : string.Empty;
            if (strings.Exists(s => s.Contains(item.ChineseName, StringComparison.OrdinalIgnoreCase) || s.Contains(item.Slug, StringComparison.OrdinalIgnoreCase)))
            {
                reason = reason.Length == 0 ? $"names {item.ChineseName}" : $"{reason}; names {item.ChineseName}";
            }

            if (reason.Length > 0)
            {
                mentioned.Add($"{item.Slug} ({reason})");
            }
        }

        return mentioned;
    }

    // The string GetTeamName (the original's) or get_TeamName (the SDK's) returns when its body only loads a constant and returns it.
    private static string? ConstantTeamName(PEReader pe, MetadataReader metadata)
    {
        foreach (var typeHandle in metadata.TypeDefinitions)
        {
            foreach (var methodHandle in metadata.GetTypeDefinition(typeHandle).GetMethods())
            {
                var method = metadata.GetMethodDefinition(methodHandle);
                string name = metadata.GetString(method.Name);
                if (name is "GetTeamName" or "get_TeamName" && method.RelativeVirtualAddress != 0
                    && ConstantReturned(pe.GetMethodBody(method.RelativeVirtualAddress).GetILBytes(), metadata) is { } constant)
                {
                    return constant;
                }
            }
        }

        return null;
    }

    // Accepts nop, ldstr, stloc/ldloc and branches (a debug build's return through a local), one ldstr and ret.
    private static string? ConstantReturned(byte[]? il, MetadataReader metadata)
    {
        string? value = null;
        for (int i = 0; il is not null && i < il.Length;)
        {
            switch (il[i])
            {
                case 0x00 or 0x06 or 0x0A: // nop, ldloc.0, stloc.0
                    i += 1;
                    break;
                case 0x11 or 0x13 or 0x2B: // ldloc.s, stloc.s, br.s
                    i += 2;
                    break;
                case 0x38: // br
                    i += 5;
                    break;
                case 0x72 when value is null && i + 5 <= il.Length: // ldstr
                    value = metadata.GetUserString(MetadataTokens.UserStringHandle(BitConverter.ToInt32(il, i + 1) & 0xFFFFFF));
                    i += 5;
                    break;
                case 0x2A: // ret
                    return value;
                default:
                    return null;
            }
        }

        return null;
    }
}
