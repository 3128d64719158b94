using System;
using System.IO;
using System.Reflection;
using System.Runtime.Loader;

namespace URWPGSim2D.Compat.Retargeting;

/// <summary>
/// Loads a strategy assembly into its load context, retargeting one built for the original on the way:
/// an image that references the original's assemblies (<see cref="OriginalReferences"/>) or demands a
/// 32-bit process is rewritten in memory (<see cref="ImageRetargeter"/>) and loaded from the bytes, so
/// nothing is written to disk and the file is never changed; any other assembly loads from its file as
/// before. An image holding native code is refused. Failures throw <see cref="BadImageFormatException"/>
/// or <see cref="FileLoadException"/> with a one-line message.
/// </summary>
internal static class OriginalAssemblyLoader
{
    /// <summary>Loads the strategy assembly at <paramref name="path"/> into <paramref name="context"/>.</summary>
    /// <param name="context">The team's strategy load context.</param>
    /// <param name="path">Full path of the assembly file.</param>
    /// <returns>The loaded assembly.</returns>
    public static Assembly Load(AssemblyLoadContext context, string path)
    {
        ArgumentNullException.ThrowIfNull(context);
        byte[] image;
        try
        {
            image = File.ReadAllBytes(path);
        }
        catch (UnauthorizedAccessException e)
        {
            throw new FileLoadException(e.Message, path, e);
        }

        ImageShape? shape = ImageShape.Read(image);
        if (shape is null)
        {
            // Not a managed PE image: the runtime's loader says why.
            return context.LoadFromAssemblyPath(path);
        }

        if (!shape.ILOnly)
        {
            throw new BadImageFormatException(
                "it holds native code (its CLR header is not IL-only, as in a mixed-mode C++/CLI assembly); only IL-only assemblies can run here");
        }

        if (!shape.NeedsRetargeting)
        {
            return context.LoadFromAssemblyPath(path);
        }

        byte[] retargeted = ImageRetargeter.Retarget(image);
        Assembly assembly;
        using (var stream = new MemoryStream(retargeted, writable: false))
        {
            assembly = context.LoadFromStream(stream);
        }

        RetargetedReferenceCheck.ThrowIfMissing(assembly, retargeted);
        return assembly;
    }
}
