using System;
using System.Collections.Generic;
using System.Collections.Immutable;
using System.IO;
using System.Linq;
using System.Reflection.Metadata;
using System.Reflection.Metadata.Ecma335;
using System.Reflection.PortableExecutable;
using System.Security.Cryptography;
using Microsoft.CodeAnalysis;
using Microsoft.CodeAnalysis.CSharp;
using Microsoft.CodeAnalysis.Emit;

namespace URWPGSim2D.Tests.OldStrategies;

/// <summary>
/// Compiles a strategy DLL in the shape of those built for the original: PE32, machine I386, CLR flags
/// ILONLY | 32BITREQUIRED (or ILONLY only for AnyCPU), metadata version v2.0.50727, references to
/// <c>mscorlib 2.0.0.0 (b77a5c561934e089)</c>, <c>System.Drawing 2.0.0.0 (b03f5f7f11d50a3a)</c>, the
/// original's assemblies <c>1.2.123.20110 (04f000b8db128100)</c> and <c>Microsoft.Xna.Framework 3.1.0.0
/// (6d5c3888ef60e27d)</c>. The referenced assemblies are stand-ins compiled here
/// (<see cref="FrameworkStubs"/>, <see cref="OriginalApiStubs"/>), public-signed with keys made for the
/// run; a key whose token is a given one cannot be made, so the tokens in the DLL's assembly references
/// are then set to the real ones (same length, in place). Nothing here comes from the original's binaries.
/// </summary>
internal static class OldStrategyCompiler
{
    /// <summary>The public key token of the original's assemblies.</summary>
    public const string OriginalToken = "04f000b8db128100";

    /// <summary>The public key token of XNA Game Studio 3.1's assemblies.</summary>
    public const string XnaToken = "6d5c3888ef60e27d";

    private static readonly Lazy<References> Stubs = new(() => Build(null));

    private static readonly Lazy<References> StubsWithMatrix = new(() => Build(
        "namespace Microsoft.Xna.Framework { public struct Matrix { public static Matrix Identity { get { throw null; } } } }"));

    private static readonly System.Collections.Concurrent.ConcurrentDictionary<string, Lazy<References>> StubsWithExtra = new();

    /// <summary>Compiles <paramref name="sources"/> into an old-style strategy DLL image.</summary>
    public static byte[] Compile(string assemblyName, Platform platform, params string[] sources) =>
        Compile(Stubs.Value, assemblyName, platform, sources);

    /// <summary>
    /// Compiles against stand-ins in which XNA also has <c>Matrix</c> (which the compatibility assembly
    /// does not provide), as a DLL using more of XNA than the original's API would be.
    /// </summary>
    public static byte[] CompileWithXnaMatrix(string assemblyName, params string[] sources) =>
        Compile(StubsWithMatrix.Value, assemblyName, Platform.X86, sources);

    /// <summary>
    /// Compiles against stand-ins that also have .NET Framework 2.0's <c>System.Windows.Forms</c> (with
    /// <c>MessageBox.Show</c>), which this runtime does not have, as a DLL that shows a message box.
    /// </summary>
    public static byte[] CompileWithWindowsForms(string assemblyName, params string[] sources) =>
        CompileWithExtraAssembly("System.Windows.Forms", "b77a5c561934e089", """
            [assembly: System.Reflection.AssemblyVersion("2.0.0.0")]
            namespace System.Windows.Forms { public static class MessageBox { public static int Show(string text) { return 0; } } }
            """, assemblyName, sources);

    /// <summary>
    /// Compiles against the stand-ins and one more assembly, <paramref name="extraName"/> (public key token
    /// <paramref name="token"/>), made of <paramref name="extraSource"/>: a DLL referencing an assembly that is not here.
    /// </summary>
    public static byte[] CompileWithExtraAssembly(string extraName, string token, string extraSource, string assemblyName, params string[] sources) =>
        Compile(StubsWithExtra.GetOrAdd(extraName + "|" + extraSource, _ => new Lazy<References>(() => Build(null, (extraName, extraSource, token)))).Value, assemblyName, Platform.X86, sources);

    /// <summary>Compiles <paramref name="sources"/> into an old-style strategy DLL image holding the manifest resources <paramref name="resources"/>.</summary>
    public static byte[] CompileWithResources(string assemblyName, IReadOnlyList<(string Name, byte[] Data)> resources, params string[] sources) =>
        Compile(Stubs.Value, assemblyName, Platform.X86, sources, resources);

    private static byte[] Compile(References references, string assemblyName, Platform platform, string[] sources, IReadOnlyList<(string Name, byte[] Data)>? resources = null)
    {
        var compilation = CSharpCompilation.Create(
            assemblyName,
            sources.Select(s => CSharpSyntaxTree.ParseText(s, new CSharpParseOptions(LanguageVersion.CSharp3))),
            references.All,
            new CSharpCompilationOptions(OutputKind.DynamicallyLinkedLibrary, platform: platform, optimizationLevel: OptimizationLevel.Release));
        byte[] image = Emit(compilation, null, resources);
        return SetTokens(image, references.Tokens);
    }

    /// <summary>Writes the image to a fresh temporary folder as <paramref name="fileName"/> and returns its path.</summary>
    public static string WriteTemporary(string fileName, byte[] image)
    {
        string folder = Path.Combine(Path.GetTempPath(), "urwpg-old-" + Guid.NewGuid().ToString("N"));
        Directory.CreateDirectory(folder);
        string path = Path.Combine(folder, fileName);
        File.WriteAllBytes(path, image);
        return path;
    }

    private static References Build(string? extraXna, (string Name, string Source, string Token)? extra = null)
    {
        var all = new List<MetadataReference>();
        var tokens = new Dictionary<string, string>();
        all.Add(Stub("mscorlib", FrameworkStubs.Mscorlib, [], "b77a5c561934e089", tokens));
        all.Add(Stub("System.Drawing", FrameworkStubs.SystemDrawing, all, "b03f5f7f11d50a3a", tokens));
        if (extra is { } more)
        {
            all.Add(Stub(more.Name, more.Source, all, more.Token, tokens));
        }

        foreach (var (assembly, _) in OriginalApiStubs.Assemblies)
        {
            all.Add(Stub(assembly, OriginalApiStubs.Source(assembly) + (assembly == "Microsoft.Xna.Framework" ? extraXna : null), all, assembly.StartsWith("Microsoft", StringComparison.Ordinal) ? XnaToken : OriginalToken, tokens));
        }

        return new References(all, tokens);
    }

    private static MetadataReference Stub(string name, string source, List<MetadataReference> references, string token, Dictionary<string, string> tokens)
    {
        byte[] key = PublicKeyBlob();
        tokens[Hex(TokenOf(key))] = token;
        var compilation = CSharpCompilation.Create(
            name,
            [CSharpSyntaxTree.ParseText(source)],
            references.ToArray(),
            new CSharpCompilationOptions(OutputKind.DynamicallyLinkedLibrary, cryptoPublicKey: ImmutableArray.Create(key), publicSign: true, nullableContextOptions: NullableContextOptions.Disable)
                .WithSpecificDiagnosticOptions([new("CS0169", ReportDiagnostic.Suppress), new("CS0649", ReportDiagnostic.Suppress), new("CS0660", ReportDiagnostic.Suppress), new("CS0661", ReportDiagnostic.Suppress)]));
        return MetadataReference.CreateFromImage(Emit(compilation, references.Count == 0 ? "v2.0.50727" : null));
    }

    private static byte[] Emit(CSharpCompilation compilation, string? runtimeVersion, IReadOnlyList<(string Name, byte[] Data)>? resources = null)
    {
        using var stream = new MemoryStream();
        var manifest = resources?.Select(r => new ResourceDescription(r.Name, () => new MemoryStream(r.Data), isPublic: true));
        var result = compilation.Emit(stream, manifestResources: manifest, options: new EmitOptions(runtimeMetadataVersion: runtimeVersion));
        if (!result.Success)
        {
            throw new InvalidOperationException($"{compilation.AssemblyName}: " + string.Join("\n", result.Diagnostics.Where(d => d.Severity == DiagnosticSeverity.Error).Take(20)));
        }

        return stream.ToArray();
    }

    /// <summary>Sets the public key token of each assembly reference whose stand-in token is in <paramref name="tokens"/>.</summary>
    private static byte[] SetTokens(byte[] image, Dictionary<string, string> tokens)
    {
        byte[] patched = (byte[])image.Clone();
        using var pe = new PEReader(ImmutableArray.Create(image));
        var metadata = pe.GetMetadataReader();
        int blobs = pe.PEHeaders.MetadataStartOffset + metadata.GetHeapMetadataOffset(HeapIndex.Blob);
        var done = new HashSet<int>();
        foreach (var handle in metadata.AssemblyReferences)
        {
            var blob = metadata.GetAssemblyReference(handle).PublicKeyOrToken;
            byte[] token = metadata.GetBlobBytes(blob);
            if (token.Length != 8 || !tokens.TryGetValue(Hex(token), out string? wanted))
            {
                continue;
            }

            int offset = blobs + MetadataTokens.GetHeapOffset(blob) + 1;
            if (done.Add(offset))
            {
                Convert.FromHexString(wanted).CopyTo(patched, offset);
            }
        }

        return patched;
    }

    /// <summary>A fresh RSA public key in the strong-name public key blob format.</summary>
    private static byte[] PublicKeyBlob()
    {
        using var rsa = RSA.Create(1024);
        var p = rsa.ExportParameters(false);
        var blob = new List<byte>();
        blob.AddRange(BitConverter.GetBytes(0x2400u));
        blob.AddRange(BitConverter.GetBytes(0x8004u));
        blob.AddRange(BitConverter.GetBytes((uint)(20 + p.Modulus!.Length)));
        blob.AddRange([0x06, 0x02, 0x00, 0x00]);
        blob.AddRange(BitConverter.GetBytes(0x2400u));
        blob.AddRange(BitConverter.GetBytes(0x31415352u));
        blob.AddRange(BitConverter.GetBytes((uint)(p.Modulus.Length * 8)));
        byte[] exponent = new byte[4];
        for (int i = 0; i < p.Exponent!.Length; i++)
        {
            exponent[i] = p.Exponent[p.Exponent.Length - 1 - i];
        }

        blob.AddRange(exponent);
        blob.AddRange(p.Modulus.Reverse());
        return blob.ToArray();
    }

    private static byte[] TokenOf(byte[] publicKey) => SHA1.HashData(publicKey)[^8..].Reverse().ToArray();

    private static string Hex(byte[] bytes) => Convert.ToHexString(bytes).ToLowerInvariant();

    private sealed record References(List<MetadataReference> All, Dictionary<string, string> Tokens);
}
