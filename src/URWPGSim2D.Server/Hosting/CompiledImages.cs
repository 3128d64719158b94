using System;
using System.Collections.Concurrent;
using System.Collections.Generic;
using System.Diagnostics;
using System.Globalization;
using System.IO;
using System.Security.Cryptography;
using System.Text;

namespace URWPGSim2D.Server.Hosting;

/// <summary>
/// Strategy sources compiled once per run: the image of a folder or <c>.cs</c> file is kept, keyed
/// by the path and a SHA-256 of its files' names and contents, so every match of a batch (and every
/// host) uses the same compiled assembly and a changed file is compiled again.
/// </summary>
internal static class CompiledImages
{
    private static readonly ConcurrentDictionary<string, Lazy<byte[]>> Images = new(StringComparer.Ordinal);
    private static readonly ConcurrentDictionary<string, string> Files = new(StringComparer.Ordinal);

    /// <summary>The compiled image of the sources <paramref name="files"/> of <paramref name="path"/>.</summary>
    /// <param name="path">The spec's folder or file, as the user wrote it.</param>
    /// <param name="files">Its source files.</param>
    /// <param name="progress">Told a line when compiling starts and one when it is done (with the time it took); not told when the image is already compiled.</param>
    /// <exception cref="StrategyLoadException">They do not compile (the message names <paramref name="path"/>).</exception>
    public static byte[] Get(string path, IReadOnlyList<string> files, Action<string>? progress = null)
    {
        string key = Key(path, files);
        var lazy = Images.GetOrAdd(key, _ => new Lazy<byte[]>(() => Compile(path, files, progress)));
        try
        {
            return lazy.Value;
        }
        catch (StrategyLoadException)
        {
            Images.TryRemove(key, out _);
            throw;
        }
    }

    /// <summary>The compiled image of <paramref name="path"/>'s sources written to a file of this run's folder (once), for a strategy host to load.</summary>
    /// <param name="path">The spec's folder or file, as the user wrote it.</param>
    /// <param name="files">Its source files.</param>
    /// <param name="progress">As for <see cref="Get"/>.</param>
    public static string File(string path, IReadOnlyList<string> files, Action<string>? progress = null)
    {
        byte[] image = Get(path, files, progress);
        string key = Key(path, files);
        return Files.GetOrAdd(key, _ =>
        {
            string file = System.IO.Path.Combine(RunFolder.NewStrategyFolder(), Name(path) + ".dll");
            System.IO.File.WriteAllBytes(file, image);
            return file;
        });
    }

    /// <summary>
    /// Forgets every compiled image, as a new process starts without them: for tests that show
    /// what separate runs print (each compiles its strategies again, with its progress lines).
    /// </summary>
    internal static void Forget()
    {
        Images.Clear();
        Files.Clear();
    }

    /// <summary>The assembly name of a compiled strategy.</summary>
    public static string Name(string path) => "Strategy_" + System.IO.Path.GetFileNameWithoutExtension(System.IO.Path.TrimEndingDirectorySeparator(path));

    private static byte[] Compile(string path, IReadOnlyList<string> files, Action<string>? progress)
    {
        try
        {
            progress?.Invoke(string.Create(CultureInfo.InvariantCulture, $"compiling {path} ({files.Count} file{(files.Count == 1 ? string.Empty : "s")})..."));
            long start = Stopwatch.GetTimestamp();
            byte[] image = StrategyCompiler.Compile(Name(path), files, progress);
            progress?.Invoke(string.Create(CultureInfo.InvariantCulture, $"compiled {path} in {Stopwatch.GetElapsedTime(start).TotalSeconds:0.0} s"));
            return image;
        }
        catch (StrategyLoadException e)
        {
            throw new StrategyLoadException($"cannot compile {path}: {e.Message}", e.Details);
        }
    }

    private static string Key(string path, IReadOnlyList<string> files)
    {
        using var sha = IncrementalHash.CreateHash(HashAlgorithmName.SHA256);
        foreach (string file in files)
        {
            sha.AppendData(Encoding.UTF8.GetBytes(file + "\n"));
            try
            {
                sha.AppendData(System.IO.File.ReadAllBytes(file));
            }
            catch (Exception e) when (e is IOException or UnauthorizedAccessException)
            {
                throw new StrategyLoadException($"cannot read {file}: {e.Message}");
            }
        }

        return System.IO.Path.GetFullPath(path) + "|" + Convert.ToHexString(sha.GetHashAndReset());
    }
}
