using System.Collections.Immutable;
using System.Reflection.Metadata;
using System.Reflection.PortableExecutable;

namespace URWPGSim2D.Compat.Retargeting;

/// <summary>What the loader needs to know of a PE image: whether it is IL only, and whether it must be
/// retargeted (it demands a 32-bit process or references one of the original's assemblies).</summary>
/// <param name="ILOnly">The CLR header's ILONLY flag: the image holds no native code.</param>
/// <param name="Requires32Bit">The CLR header's 32BITREQUIRED flag (an x86 build).</param>
/// <param name="ReferencesOriginal">Whether an assembly reference names one of the original's assemblies.</param>
internal sealed record ImageShape(bool ILOnly, bool Requires32Bit, bool ReferencesOriginal)
{
    /// <summary>Whether the image must be rewritten before it can load in this process.</summary>
    public bool NeedsRetargeting => Requires32Bit || ReferencesOriginal;

    /// <summary>Reads the shape of <paramref name="image"/>, or null when it is not a managed PE image.</summary>
    /// <param name="image">The file's bytes.</param>
    public static ImageShape? Read(byte[] image)
    {
        try
        {
            using var pe = new PEReader(ImmutableArray.Create(image));
            if (pe.PEHeaders.CorHeader is not { } cor || !pe.HasMetadata)
            {
                return null;
            }

            var metadata = pe.GetMetadataReader();
            bool original = false;
            foreach (var handle in metadata.AssemblyReferences)
            {
                original |= OriginalReferences.IsOriginal(metadata.GetString(metadata.GetAssemblyReference(handle).Name));
            }

            return new ImageShape(
                (cor.Flags & CorFlags.ILOnly) != 0,
                (cor.Flags & CorFlags.Requires32Bit) != 0,
                original);
        }
        catch (BadImageFormatException)
        {
            return null;
        }
    }
}
