using System;
using System.Collections.Generic;
using System.Globalization;
using System.IO;
using System.IO.Compression;
using System.Linq;

namespace URWPGSim2D.Ladder.Play;

/// <summary>
/// Turns an upload into a submission's files: one <c>.cs</c> file, several <c>.cs</c> files (a
/// folder), one <c>.zip</c> of a folder of sources, or one <c>.dll</c> (built for this server or
/// for the original). Sizes and file counts are limited; every name is checked so that no file
/// lands outside the submission's folder (no <c>..</c>, no rooted path, no separators in a plain
/// file's name). Files are written to a folder beside the final one and moved into place whole.
/// </summary>
internal static class Uploads
{
    /// <summary>The kinds of submission: one source file, a folder of sources, an assembly.</summary>
    public const string SourceFile = "cs", SourceFolder = "folder", Assembly = "dll";

    /// <summary>Checks an upload against the limits; throws <see cref="UploadException"/> with one line when it breaks one.</summary>
    public static void CheckLimits(IReadOnlyList<UploadedFile> files, LadderLimits limits)
    {
        if (files.Count == 0)
        {
            throw new UploadException("upload: no file given (one .cs, several .cs, one .zip of sources or one .dll)");
        }

        if (files.Count > limits.MaxFiles)
        {
            throw new UploadException(Inv($"upload: {files.Count} files, more than the limit of {limits.MaxFiles}"));
        }

        long total = files.Sum(f => (long)f.Bytes.Length);
        if (total > limits.MaxUploadBytes)
        {
            throw new UploadException(Inv($"upload: {total} bytes, more than the limit of {limits.MaxUploadBytes}"));
        }
    }

    /// <summary>
    /// Writes the upload into <paramref name="folder"/> (which must not exist yet) and returns the
    /// submission's kind and its team SPEC (a path under the folder).
    /// </summary>
    public static (string Kind, string Spec) Write(IReadOnlyList<UploadedFile> files, string folder, LadderLimits limits)
    {
        CheckLimits(files, limits);
        var names = files.Select(f => SafeName(f.Name)).ToArray();
        string kind;
        if (files.Count == 1 && names[0].EndsWith(".dll", StringComparison.OrdinalIgnoreCase))
        {
            kind = Assembly;
        }
        else if (files.Count == 1 && names[0].EndsWith(".zip", StringComparison.OrdinalIgnoreCase))
        {
            kind = SourceFolder;
        }
        else if (names.All(n => n.EndsWith(".cs", StringComparison.OrdinalIgnoreCase)))
        {
            kind = files.Count == 1 ? SourceFile : SourceFolder;
        }
        else
        {
            string odd = names.First(n => !n.EndsWith(".cs", StringComparison.OrdinalIgnoreCase));
            throw new UploadException($"upload: {Quote(odd)} is not a .cs file (give .cs files, one .zip of sources or one .dll)");
        }

        if (names.Distinct(StringComparer.OrdinalIgnoreCase).Count() != names.Length)
        {
            throw new UploadException("upload: two files have the same name");
        }

        string partial = folder + ".part";
        if (Directory.Exists(partial))
        {
            Directory.Delete(partial, recursive: true);
        }

        Directory.CreateDirectory(partial);
        string spec;
        try
        {
            if (kind == SourceFolder && names[0].EndsWith(".zip", StringComparison.OrdinalIgnoreCase))
            {
                Extract(files[0].Bytes, Path.Combine(partial, "src"), limits);
                spec = Path.Combine(folder, "src");
            }
            else if (kind == SourceFolder)
            {
                Directory.CreateDirectory(Path.Combine(partial, "src"));
                for (int i = 0; i < files.Count; i++)
                {
                    File.WriteAllBytes(Path.Combine(partial, "src", names[i]), files[i].Bytes);
                }

                spec = Path.Combine(folder, "src");
            }
            else
            {
                File.WriteAllBytes(Path.Combine(partial, names[0]), files[0].Bytes);
                spec = Path.Combine(folder, names[0]);
            }

            Directory.Move(partial, folder);
        }
        catch
        {
            if (Directory.Exists(partial))
            {
                Directory.Delete(partial, recursive: true);
            }

            throw;
        }

        return (kind, spec);
    }

    // A plain file name: no folder part, no control characters, not . or ..
    private static string SafeName(string name)
    {
        if (name.Length == 0 || name.Length > 200 || name is "." or ".." || name.IndexOfAny(['/', '\\', ':']) >= 0 || name.Any(char.IsControl))
        {
            throw new UploadException($"upload: file name {Quote(name)} is not a plain file name");
        }

        return name;
    }

    // The .cs files of a zip archive into `target`; any entry whose path would leave it, or that is not a .cs file or a folder, refuses the whole upload.
    private static void Extract(byte[] bytes, string target, LadderLimits limits)
    {
        string root = Path.GetFullPath(target) + Path.DirectorySeparatorChar;
        ZipArchive archive;
        try
        {
            archive = new ZipArchive(new MemoryStream(bytes, writable: false), ZipArchiveMode.Read);
        }
        catch (InvalidDataException e)
        {
            throw new UploadException($"upload: the .zip cannot be read ({Line(e.Message)})");
        }

        using (archive)
        {
            if (archive.Entries.Count > limits.MaxFiles)
            {
                throw new UploadException(Inv($"upload: the .zip holds {archive.Entries.Count} entries, more than the limit of {limits.MaxFiles}"));
            }

            long unpacked = 0;
            var entries = new List<(ZipArchiveEntry Entry, string Path)>();
            foreach (var entry in archive.Entries)
            {
                string name = entry.FullName.Replace('\\', '/');
                if (name.Length == 0 || name.StartsWith('/') || name.Split('/').Any(p => p == "..") || Path.IsPathRooted(name) || name.Contains(':', StringComparison.Ordinal) || name.Any(char.IsControl))
                {
                    throw new UploadException($"upload: the .zip entry {Quote(entry.FullName)} leaves its folder");
                }

                string full = Path.GetFullPath(Path.Combine(target, name));
                if (!full.StartsWith(root, StringComparison.Ordinal) && full + Path.DirectorySeparatorChar != root)
                {
                    throw new UploadException($"upload: the .zip entry {Quote(entry.FullName)} leaves its folder");
                }

                if (name.EndsWith('/'))
                {
                    continue;
                }

                if (!name.EndsWith(".cs", StringComparison.OrdinalIgnoreCase))
                {
                    throw new UploadException($"upload: the .zip entry {Quote(entry.FullName)} is not a .cs file");
                }

                unpacked += entry.Length;
                if (unpacked > limits.MaxUnpackedBytes)
                {
                    throw new UploadException(Inv($"upload: the .zip unpacks to more than the limit of {limits.MaxUnpackedBytes} bytes"));
                }

                entries.Add((entry, full));
            }

            if (entries.Count == 0)
            {
                throw new UploadException("upload: the .zip holds no .cs file");
            }

            Directory.CreateDirectory(target);
            foreach (var (entry, full) in entries)
            {
                Directory.CreateDirectory(Path.GetDirectoryName(full)!);
                using var input = entry.Open();
                using var output = File.Create(full);
                CopyAtMost(input, output, limits.MaxUnpackedBytes, entry.FullName);
            }
        }
    }

    // Copies, refusing more bytes than the limit (an entry may claim a smaller size than it unpacks to).
    private static void CopyAtMost(Stream input, Stream output, long limit, string name)
    {
        byte[] buffer = new byte[81920];
        long copied = 0;
        int n;
        while ((n = input.Read(buffer, 0, buffer.Length)) > 0)
        {
            copied += n;
            if (copied > limit)
            {
                throw new UploadException(Inv($"upload: the .zip entry {Quote(name)} unpacks to more than the limit of {limit} bytes"));
            }

            output.Write(buffer, 0, n);
        }
    }

    private static string Quote(string s) => Engine.Messages.MessageText.Quote(s);

    private static string Line(string s) => s.ReplaceLineEndings(" ");

    private static string Inv(FormattableString s) => s.ToString(CultureInfo.InvariantCulture);
}
