using System.IO;
using Mono.Cecil;

namespace URWPGSim2D.Compat.Retargeting;

/// <summary>
/// Rewrites, in memory, an assembly image built for the original so that it loads in this process: every
/// type reference into one of the original's assemblies (<see cref="OriginalReferences"/>) is scoped to the
/// compatibility assembly instead, those assembly references are dropped, and the 32BITREQUIRED and
/// strong-name-signed flags are cleared (an IL-only image runs in any process; the rewritten image is not
/// signed). Everything else — the IL, its other references (<c>mscorlib 2.0.0.0</c> and the framework's
/// assemblies resolve to this runtime's own), resources — is kept as it was: the image is read lazily,
/// so attribute blobs and method bodies are copied untouched, and where Mono.Cecil must look into a
/// referenced assembly, <see cref="RuntimeAssemblyResolver"/> answers from the running runtime.
/// </summary>
internal static class ImageRetargeter
{
    /// <summary>The rewritten image of <paramref name="image"/>.</summary>
    /// <param name="image">The original file's bytes (not changed).</param>
    /// <returns>A new image.</returns>
    /// <exception cref="BadImageFormatException">The image cannot be read or rewritten.</exception>
    public static byte[] Retarget(byte[] image)
    {
        try
        {
            using var input = new MemoryStream(image, writable: false);
            using var resolver = new RuntimeAssemblyResolver();
            using var module = ModuleDefinition.ReadModule(input, new ReaderParameters
            {
                // Deferred: what is not changed (attribute blobs, method bodies) is copied as it was,
                // so nothing needs another assembly's contents unless Cecil must decode it.
                ReadingMode = ReadingMode.Deferred,
                ReadSymbols = false,
                InMemory = true,
                AssemblyResolver = resolver,
            });
            Rescope(module);
            module.Attributes &= ~(ModuleAttributes.Required32Bit | ModuleAttributes.Preferred32Bit | ModuleAttributes.StrongNameSigned);
            using var output = new MemoryStream();
            module.Write(output);
            return output.ToArray();
        }
        catch (Exception e) when (e is not OutOfMemoryException)
        {
            throw new BadImageFormatException($"cannot retarget it to the compatibility assembly: {e.Message}", e);
        }
    }

    private static void Rescope(ModuleDefinition module)
    {
        var compat = new AssemblyNameReference(OriginalReferences.Compat.Name, OriginalReferences.Compat.Version)
        {
            Culture = string.Empty,
            PublicKeyToken = OriginalReferences.Compat.GetPublicKeyToken() ?? [],
        };
        var originals = new List<AssemblyNameReference>();
        foreach (var reference in module.AssemblyReferences)
        {
            if (OriginalReferences.IsOriginal(reference.Name))
            {
                originals.Add(reference);
            }
        }

        if (originals.Count == 0)
        {
            return;
        }

        module.AssemblyReferences.Add(compat);
        foreach (var type in module.GetTypeReferences())
        {
            if (type.Scope is AssemblyNameReference scope && originals.Contains(scope))
            {
                type.Scope = compat;
            }
        }

        // A type the old assembly forwarded to one of the original's assemblies now lives in the compatibility assembly.
        foreach (var exported in module.ExportedTypes)
        {
            if (exported.Scope is AssemblyNameReference scope && originals.Contains(scope))
            {
                exported.Scope = compat;
            }
        }

        foreach (var reference in originals)
        {
            module.AssemblyReferences.Remove(reference);
        }
    }
}
