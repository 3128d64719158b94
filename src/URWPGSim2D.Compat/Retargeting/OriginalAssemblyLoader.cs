using System.Collections.Concurrent;
using System.IO;
using System.Reflection;
using System.Runtime.Loader;
using System.Security.Cryptography;

namespace URWPGSim2D.Compat.Retargeting;

/// <summary>
/// Loads a strategy assembly into its load context, retargeting one built for the original on the way:
/// an image that references the original's assemblies (<see cref="OriginalReferences"/>) or demands a
/// 32-bit process is rewritten in memory (<see cref="ImageRetargeter"/>) and loaded from the bytes, so
/// nothing is written beside the file and the file is never changed; any other assembly loads from its
/// file as before. An image holding native code is refused. Failures throw
/// <see cref="BadImageFormatException"/> or <see cref="FileLoadException"/> with a one-line message.
/// A file is read once per process (again only when its size or time changes) and an image is
/// retargeted once per content (keyed by its SHA-256), so the matches of a batch or tournament share it.
/// </summary>
public static class OriginalAssemblyLoader
{
    private static readonly ConcurrentDictionary<(string Path, long Length, DateTime Written), Lazy<LoadableImage>> Files = new();
    private static readonly ConcurrentDictionary<string, Lazy<byte[]>> Retargeted = new(StringComparer.Ordinal);

    /// <summary>Loads the strategy assembly at <paramref name="path"/> into <paramref name="context"/>.</summary>
    /// <param name="context">The team's strategy load context.</param>
    /// <param name="path">Full path of the assembly file.</param>
    /// <returns>The loaded assembly.</returns>
    public static Assembly Load(AssemblyLoadContext context, string path)
    {
        ArgumentNullException.ThrowIfNull(context);
        var image = Read(path);
        if (image.Retargeted is null)
        {
            // Not a managed image (the runtime's loader says why), or one this runtime loads as it is.
            return context.LoadFromAssemblyPath(path);
        }

        Assembly assembly;
        using (var stream = new MemoryStream(image.Retargeted, writable: false))
        {
            assembly = context.LoadFromStream(stream);
        }

        RetargetedReferenceCheck.ThrowIfMissing(assembly, image.Retargeted);
        return assembly;
    }

    /// <summary>
    /// The image of the file at <paramref name="path"/> as this runtime loads it: retargeted when it was
    /// built for the original (<see cref="LoadableImage.Retargeted"/>), else only its content hash.
    /// </summary>
    /// <param name="path">Full path of the assembly file.</param>
    /// <exception cref="BadImageFormatException">It holds native code, or cannot be retargeted.</exception>
    /// <exception cref="FileLoadException">It cannot be read.</exception>
    public static LoadableImage Read(string path)
    {
        FileInfo info;
        try
        {
            info = new FileInfo(path);
            info.Refresh();
        }
        catch (Exception e) when (e is ArgumentException or NotSupportedException or PathTooLongException)
        {
            throw new FileLoadException(e.Message, path, e);
        }

        var key = (info.FullName, info.Exists ? info.Length : -1, info.Exists ? info.LastWriteTimeUtc : default);
        var lazy = Files.GetOrAdd(key, k => new Lazy<LoadableImage>(() => ReadFile(k.Path)));
        try
        {
            return lazy.Value;
        }
        catch (Exception)
        {
            Files.TryRemove(key, out _);
            throw;
        }
    }

    private static LoadableImage ReadFile(string path)
    {
        byte[] bytes;
        try
        {
            bytes = File.ReadAllBytes(path);
        }
        catch (UnauthorizedAccessException e)
        {
            throw new FileLoadException(e.Message, path, e);
        }

        string hash = Convert.ToHexStringLower(SHA256.HashData(bytes));
        ImageShape? shape = ImageShape.Read(bytes);
        if (shape is null)
        {
            return new LoadableImage(hash, null);
        }

        if (!shape.ILOnly)
        {
            throw new BadImageFormatException(
                "it holds native code (its CLR header is not IL-only, as in a mixed-mode C++/CLI assembly); only IL-only assemblies can run here");
        }

        if (!shape.NeedsRetargeting)
        {
            return new LoadableImage(hash, null);
        }

        var lazy = Retargeted.GetOrAdd(hash, _ => new Lazy<byte[]>(() => ImageRetargeter.Retarget(bytes)));
        try
        {
            return new LoadableImage(hash, lazy.Value);
        }
        catch (BadImageFormatException)
        {
            Retargeted.TryRemove(hash, out _);
            throw;
        }
    }
}

/// <summary>A strategy assembly's image as this runtime loads it (<see cref="OriginalAssemblyLoader.Read"/>).</summary>
/// <param name="Sha256">The SHA-256 of the file's bytes, in lower-case hex.</param>
/// <param name="Retargeted">The retargeted image when the file was built for the original, else null (the file loads as it is).</param>
public sealed record LoadableImage(string Sha256, byte[]? Retargeted);
