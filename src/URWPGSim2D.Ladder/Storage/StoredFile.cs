using System;
using System.IO;
using System.IO.Compression;
using System.Security.Cryptography;

namespace URWPGSim2D.Ladder.Storage;

/// <summary>
/// A file kept in the database: a submission's upload (its path in the submission's folder, '/'
/// between folders) or a match's output (<c>replay.html</c>, <c>outputs.json</c>), with the SHA-256 of
/// its bytes (lower-case hex), which names its copy in a data folder. The database keeps the bytes
/// gzip-compressed.
/// </summary>
internal sealed record StoredFile(string Name, string Sha256, byte[] Bytes)
{
    /// <summary>A file of these bytes.</summary>
    public static StoredFile Of(string name, byte[] bytes) => new(name, Hash(bytes), bytes);

    /// <summary>The SHA-256 of <paramref name="bytes"/>, lower-case hex.</summary>
    public static string Hash(ReadOnlySpan<byte> bytes) => Convert.ToHexStringLower(SHA256.HashData(bytes));

    /// <summary>The bytes as the database keeps them.</summary>
    public byte[] Packed()
    {
        using var packed = new MemoryStream();
        using (var gzip = new GZipStream(packed, CompressionLevel.Fastest, leaveOpen: true))
        {
            gzip.Write(Bytes);
        }

        return packed.ToArray();
    }

    /// <summary>A file read back from the database.</summary>
    public static StoredFile Unpacked(string name, string sha256, byte[] packed)
    {
        using var gzip = new GZipStream(new MemoryStream(packed, writable: false), CompressionMode.Decompress);
        using var bytes = new MemoryStream();
        gzip.CopyTo(bytes);
        return new StoredFile(name, sha256, bytes.ToArray());
    }
}
