using System.Collections.Immutable;
using System.IO;
using System.Reflection;
using System.Reflection.Metadata;
using System.Reflection.Metadata.Ecma335;
using System.Reflection.PortableExecutable;

namespace URWPGSim2D.Compat.Retargeting;

/// <summary>
/// After a retargeted image has loaded, resolves each of its references — every type it names, and every
/// field and method of those types it uses, in the compatibility assembly and in the framework alike — so
/// that a strategy using a part of the original's API the compatibility assembly does not provide, or a
/// part of .NET Framework this runtime does not have (Windows Forms, remoting, …), is refused at load
/// time naming what is missing, instead of faulting in the middle of a match.
/// </summary>
public static class RetargetedReferenceCheck
{
    private const int Named = 3;

    /// <summary>Throws <see cref="FileLoadException"/> when a reference of the image does not resolve.</summary>
    /// <param name="assembly">The loaded, retargeted assembly.</param>
    /// <param name="image">Its image.</param>
    public static void ThrowIfMissing(Assembly assembly, byte[] image)
    {
        var missing = Missing(assembly, image);
        if (missing.Count == 0)
        {
            return;
        }

        var parts = new List<string>();
        var compat = missing.FindAll(m => m.InCompatibilityAssembly);
        var framework = missing.FindAll(m => !m.InCompatibilityAssembly && IsFramework(m.Assembly));
        var others = missing.FindAll(m => !m.InCompatibilityAssembly && !IsFramework(m.Assembly));
        if (compat.Count > 0)
        {
            parts.Add("parts of the original's API that the compatibility assembly does not provide: " + List(compat));
        }

        if (framework.Count > 0)
        {
            parts.Add("parts of .NET Framework that this runtime does not have: " + List(framework));
        }

        if (others.Count > 0)
        {
            var names = new List<string>();
            foreach (var m in others)
            {
                if (!names.Contains(m.Assembly))
                {
                    names.Add(m.Assembly);
                }
            }
            parts.Add($"assemblies that are not here ({string.Join(", ", names)}): " + List(others));
        }

        throw new FileLoadException("it uses " + string.Join("; and ", parts));
    }

    /// <summary>
    /// The file a reference of a retargeted image to the assembly <paramref name="name"/> resolves to
    /// here (the compatibility assembly for the original's, a facade of the running runtime for the
    /// framework's), or null when there is none.
    /// </summary>
    /// <param name="name">A simple assembly name.</param>
    public static string? FileOf(string name)
    {
        ArgumentNullException.ThrowIfNull(name);
        return RuntimeAssemblyResolver.FileOf(name);
    }

    /// <summary>Every reference of the loaded image <paramref name="image"/> that does not resolve, in metadata order, each named once.</summary>
    /// <param name="assembly">The loaded, retargeted assembly.</param>
    /// <param name="image">Its image.</param>
    public static List<MissingReference> Missing(Assembly assembly, byte[] image)
    {
        ArgumentNullException.ThrowIfNull(assembly);
        var missing = new List<MissingReference>();
        using var pe = new PEReader(ImmutableArray.Create(image));
        var metadata = pe.GetMetadataReader();
        var module = assembly.ManifestModule;
        foreach (var handle in metadata.TypeReferences)
        {
            if (Scope(metadata, handle) is { } scope)
            {
                Check(() => module.ResolveType(MetadataTokens.GetToken(handle)), TypeName(metadata, handle), scope, missing);
            }
        }

        foreach (var handle in metadata.MemberReferences)
        {
            var member = metadata.GetMemberReference(handle);
            string name = metadata.GetString(member.Name);
            int token = MetadataTokens.GetToken(handle);
            if (member.Parent.Kind == HandleKind.TypeReference)
            {
                var parent = (TypeReferenceHandle)member.Parent;
                if (Scope(metadata, parent) is { } scope)
                {
                    Check(() => module.ResolveMember(token), TypeName(metadata, parent) + "." + name, scope, missing);
                }
            }
            else if (member.Parent.Kind == HandleKind.TypeSpecification
                && GenericDefinition(metadata, (TypeSpecificationHandle)member.Parent) is { } definition
                && Scope(metadata, definition) is { } scope)
            {
                // A member of a generic instance (List<RoboFish>.get_Item): resolved as it is when it can be;
                // one whose instance names the method's or type's own type parameters has no context here,
                // so its name is looked up on the generic type instead.
                Check(() => ResolveInstanceMember(module, token, definition, name), TypeName(metadata, definition) + "." + name, scope, missing);
            }
        }

        return missing;
    }

    private static object? ResolveInstanceMember(Module module, int token, TypeReferenceHandle definition, string name)
    {
        try
        {
            return module.ResolveMember(token);
        }
        catch (ArgumentException)
        {
            Type? type = module.ResolveType(MetadataTokens.GetToken(definition));
            var found = type?.GetMember(name, BindingFlags.Public | BindingFlags.NonPublic | BindingFlags.Instance | BindingFlags.Static);
            return found is { Length: > 0 } ? found[0] : null;
        }
    }

    private static void Check(Func<object?> resolve, string name, string scope, List<MissingReference> missing)
    {
        bool found;
        try
        {
            found = resolve() is not null;
        }
        catch (Exception e) when (e is TypeLoadException or MissingMemberException or ArgumentException or BadImageFormatException or FileNotFoundException or FileLoadException)
        {
            found = false;
        }

        if (!found && !missing.Exists(m => m.Name == name))
        {
            missing.Add(new MissingReference(name, scope == OriginalReferences.Compat.Name, scope));
        }
    }

    // The framework's assembly names: mscorlib, System.*, Microsoft.* (other than XNA, which the compatibility assembly provides), WindowsBase, PresentationCore/Framework.
    private static bool IsFramework(string assembly) =>
        assembly is "mscorlib" or "System" or "WindowsBase" or "PresentationCore" or "PresentationFramework" or "netstandard"
        || assembly.StartsWith("System.", StringComparison.Ordinal)
        || assembly.StartsWith("Microsoft.", StringComparison.Ordinal);

    private static string List(List<MissingReference> missing)
    {
        var names = new List<string>();
        for (int i = 0; i < Math.Min(Named, missing.Count); i++)
        {
            names.Add(missing[i].Name);
        }

        string more = missing.Count > Named ? $" and {missing.Count - Named} more" : string.Empty;
        return string.Join(", ", names) + more;
    }

    // The assembly a type reference is scoped to (through its declaring types), or null when it is not an assembly's.
    private static string? Scope(MetadataReader metadata, TypeReferenceHandle handle)
    {
        var type = metadata.GetTypeReference(handle);
        while (type.ResolutionScope.Kind == HandleKind.TypeReference)
        {
            type = metadata.GetTypeReference((TypeReferenceHandle)type.ResolutionScope);
        }

        return type.ResolutionScope.Kind == HandleKind.AssemblyReference
            ? metadata.GetString(metadata.GetAssemblyReference((AssemblyReferenceHandle)type.ResolutionScope).Name)
            : null;
    }

    // The generic type of an instance signature (GENERICINST CLASS|VALUETYPE TypeRef ...), or null for any other type specification.
    private static TypeReferenceHandle? GenericDefinition(MetadataReader metadata, TypeSpecificationHandle handle)
    {
        var reader = metadata.GetBlobReader(metadata.GetTypeSpecification(handle).Signature);
        if (reader.ReadSignatureTypeCode() != SignatureTypeCode.GenericTypeInstance)
        {
            return null;
        }

        int kind = reader.ReadCompressedInteger();
        if (kind is not ((int)SignatureTypeKind.Class or (int)SignatureTypeKind.ValueType))
        {
            return null;
        }

        var type = reader.ReadTypeHandle();
        return type.Kind == HandleKind.TypeReference ? (TypeReferenceHandle)type : null;
    }

    private static string TypeName(MetadataReader metadata, TypeReferenceHandle handle)
    {
        var type = metadata.GetTypeReference(handle);
        string name = metadata.GetString(type.Name);
        if (type.ResolutionScope.Kind == HandleKind.TypeReference)
        {
            return TypeName(metadata, (TypeReferenceHandle)type.ResolutionScope) + "+" + name;
        }

        string ns = metadata.GetString(type.Namespace);
        return ns.Length == 0 ? name : ns + "." + name;
    }
}

/// <summary>A reference of a retargeted image that does not resolve here.</summary>
/// <param name="Name">The type, or the type and member (<c>Namespace.Type.Member</c>).</param>
/// <param name="InCompatibilityAssembly">Whether it is a part of the original's API (else of the framework).</param>
/// <param name="Assembly">The simple name of the assembly the image expects it in (after retargeting).</param>
public sealed record MissingReference(string Name, bool InCompatibilityAssembly, string Assembly);
