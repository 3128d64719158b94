using System;
using System.Collections.Generic;
using System.IO;
using System.Reflection;
using System.Reflection.Metadata;
using System.Reflection.Metadata.Ecma335;
using System.Reflection.PortableExecutable;

namespace URWPGSim2D.Compat.Retargeting;

/// <summary>
/// After a retargeted image has loaded, resolves each of its references into the compatibility
/// assembly — every type, and every field and method of those types — so that a strategy using a part of
/// the original's API the compatibility assembly does not provide is refused at load time, naming what
/// is missing, instead of faulting in the middle of a match.
/// </summary>
internal static class RetargetedReferenceCheck
{
    private const int Named = 3;

    /// <summary>Throws <see cref="FileLoadException"/> when a reference into the compatibility assembly does not resolve.</summary>
    /// <param name="assembly">The loaded, retargeted assembly.</param>
    /// <param name="image">Its image.</param>
    public static void ThrowIfMissing(Assembly assembly, byte[] image)
    {
        var missing = new List<string>();
        using (var pe = new PEReader(System.Collections.Immutable.ImmutableArray.Create(image)))
        {
            var metadata = pe.GetMetadataReader();
            var module = assembly.ManifestModule;
            foreach (var handle in metadata.TypeReferences)
            {
                if (IsCompat(metadata, handle))
                {
                    Resolve(() => module.ResolveType(MetadataTokens.GetToken(handle)), () => TypeName(metadata, handle), missing);
                }
            }

            foreach (var handle in metadata.MemberReferences)
            {
                var member = metadata.GetMemberReference(handle);
                if (member.Parent.Kind == HandleKind.TypeReference && IsCompat(metadata, (TypeReferenceHandle)member.Parent))
                {
                    Resolve(
                        () => module.ResolveMember(MetadataTokens.GetToken(handle)),
                        () => TypeName(metadata, (TypeReferenceHandle)member.Parent) + "." + metadata.GetString(member.Name),
                        missing);
                }
            }
        }

        if (missing.Count > 0)
        {
            string shown = string.Join(", ", missing.GetRange(0, Math.Min(Named, missing.Count)));
            string more = missing.Count > Named ? $" and {missing.Count - Named} more" : string.Empty;
            throw new FileLoadException(
                $"it uses parts of the original's API that the compatibility assembly does not provide: {shown}{more}");
        }
    }

    private static void Resolve(Func<object?> resolve, Func<string> name, List<string> missing)
    {
        try
        {
            if (resolve() is null)
            {
                missing.Add(name());
            }
        }
        catch (Exception e) when (e is TypeLoadException or MissingMemberException or ArgumentException or BadImageFormatException or FileNotFoundException or FileLoadException)
        {
            string n = name();
            if (!missing.Contains(n))
            {
                missing.Add(n);
            }
        }
    }

    private static bool IsCompat(MetadataReader metadata, TypeReferenceHandle handle)
    {
        var type = metadata.GetTypeReference(handle);
        while (type.ResolutionScope.Kind == HandleKind.TypeReference)
        {
            type = metadata.GetTypeReference((TypeReferenceHandle)type.ResolutionScope);
        }

        return type.ResolutionScope.Kind == HandleKind.AssemblyReference
            && metadata.GetString(metadata.GetAssemblyReference((AssemblyReferenceHandle)type.ResolutionScope).Name) == OriginalReferences.Compat.Name;
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
