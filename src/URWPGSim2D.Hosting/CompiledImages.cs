using System.Collections.Concurrent;
using System.Security.Cryptography;

namespace URWPGSim2D.Hosting;

/// <summary>
/// Strategy sources compiled once per run: the image of a folder or <c>.cs</c> file is kept, keyed
/// by the path and a SHA-256 of its files' names and contents, so every match of a batch (and every
/// host) uses the same compiled assembly and a changed file is compiled again. The server compiles
/// in a child process (<see cref="CompilerProcess"/>), which writes the image to a file of the run's
/// folder; a strategy host (which is a sandbox already) compiles in its own process.
/// </summary>
internal static class CompiledImages
{
    private static readonly ConcurrentDictionary<string, Lazy<Compiled>> Images = new(StringComparer.Ordinal);
    private static readonly ConcurrentDictionary<string, string> Files = new(StringComparer.Ordinal);

    /// <summary>The compiled image of the sources <paramref name="files"/> of <paramref name="path"/>.</summary>
    /// <param name="path">The spec's folder or file, as the user wrote it.</param>
    /// <param name="files">Its source files.</param>
    /// <param name="progress">Told a line when compiling starts and one when it is done (with the time it took); not told when the image is already compiled.</param>
    /// <param name="settings">The limits of the compiler's child process (null: the defaults).</param>
    /// <param name="inThisProcess">Compile in this process (a strategy host, a remote client) instead of a child.</param>
    /// <exception cref="StrategyLoadException">They do not compile, or the compiler went past a limit (the message names <paramref name="path"/>).</exception>
    public static byte[] Get(string path, IReadOnlyList<string> files, Action<string>? progress = null, HostSettings? settings = null, bool inThisProcess = false)
    {
        string key = Key(path, files);
        var lazy = Images.GetOrAdd(key, _ => new Lazy<Compiled>(() => Compile(path, files, progress, inThisProcess ? null : settings ?? HostSettings.Default)));
        try
        {
            return lazy.Value.Image;
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
    /// <param name="settings">As for <see cref="Get"/>.</param>
    public static string File(string path, IReadOnlyList<string> files, Action<string>? progress = null, HostSettings? settings = null)
    {
        byte[] image = Get(path, files, progress, settings);
        string key = Key(path, files);
        return Files.GetOrAdd(key, _ =>
        {
            if (Images.TryGetValue(key, out var compiled) && compiled.IsValueCreated && compiled.Value.File is { } written)
            {
                return written; // the compiler's child wrote it
            }

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

    // In a child limited by settings, or (null) in this process.
    private static Compiled Compile(string path, IReadOnlyList<string> files, Action<string>? progress, HostSettings? settings)
    {
        try
        {
            progress?.Invoke(string.Create(CultureInfo.InvariantCulture, $"compiling {path} ({files.Count} file{(files.Count == 1 ? string.Empty : "s")})..."));
            long start = Stopwatch.GetTimestamp();
            Compiled compiled;
            if (settings is null)
            {
                compiled = new Compiled(StrategyCompiler.Compile(Name(path), files, progress), null);
            }
            else
            {
                var (image, file) = CompilerProcess.Compile(Name(path), path, files, settings, progress);
                compiled = new Compiled(image, file);
            }

            progress?.Invoke(string.Create(CultureInfo.InvariantCulture, $"compiled {path} in {Stopwatch.GetElapsedTime(start).TotalSeconds:0.0} s"));
            return compiled;
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

    /// <summary>A compiled image, and the file the compiler's child wrote it to (null: compiled in this process).</summary>
    private sealed record Compiled(byte[] Image, string? File);
}
