using System;
using System.Collections.Concurrent;
using System.Collections.Generic;
using System.Globalization;
using System.IO;
using System.Linq;
using System.Text;
using URWPGSim2D.Ladder.Storage;

namespace URWPGSim2D.Ladder;

/// <summary>
/// The ladder's files: kept in the database (<see cref="StoredFile"/>), so that a worker on another
/// machine needs only the database, with a data folder as a cache. A submission's upload is kept when
/// it is taken and copied into <c>submissions/ID-HASH/</c> of the folder of whichever process plays it;
/// a match's outputs (its replay page, what its strategies printed) are kept with its record, in the
/// same transaction, and copied into <c>replays/match-ID-HASH.html</c> and <c>outputs/match-ID-HASH.json</c>
/// when read. HASH is the start of the content's SHA-256, so a copy is never stale and two databases
/// may share a folder. <see cref="Import"/> reads a data folder of an older version (files without
/// their hash in the name) into the database.
/// </summary>
internal sealed class LadderFiles
{
    /// <summary>A match's replay page.</summary>
    public const string Replay = "replay.html";

    /// <summary>A match's strategies' outputs (<see cref="Play.MatchOutputs"/>).</summary>
    public const string Outputs = "outputs.json";

    private readonly ILadderStore _store;
    private readonly string _dataDir;
    private readonly ConcurrentDictionary<long, string> _specs = new();
    private int _plays;

    /// <param name="store">Where the files are kept.</param>
    /// <param name="dataDir">The data folder of this process: the cache.</param>
    public LadderFiles(ILadderStore store, string dataDir)
    {
        _store = store;
        _dataDir = Path.GetFullPath(dataDir);
    }

    /// <summary>The folder of submissions' files.</summary>
    public string SubmissionsFolder => Path.Combine(_dataDir, "submissions");

    /// <summary>
    /// Keeps an upload written to <paramref name="folder"/> (its team SPEC <paramref name="spec"/> in it):
    /// its files and its path go to the database in one transaction, the folder becomes the submission's
    /// cached copy. The SPEC of the copy.
    /// </summary>
    public string Keep(long submission, string folder, string spec)
    {
        var files = Read(folder);
        string cached = SubmissionFolder(submission, files);
        if (Directory.Exists(cached))
        {
            Directory.Delete(folder, recursive: true);
        }
        else
        {
            Directory.Move(folder, cached);
        }

        string path = Path.Combine(cached, Path.GetFileName(spec));
        _store.SetSubmissionFiles(submission, path, files);
        _specs[submission] = path;
        return path;
    }

    /// <summary>
    /// The team SPEC of a submission on this machine: its copy in this data folder, made from the
    /// database when there is none yet (a submission without files in the database plays from its path).
    /// </summary>
    public string Spec(SubmissionRow submission)
    {
        if (_specs.TryGetValue(submission.Id, out string? known))
        {
            return known;
        }

        var files = _store.SubmissionFiles(submission.Id);
        if (files.Count == 0)
        {
            return submission.Path;
        }

        string folder = SubmissionFolder(submission.Id, files);
        if (!Directory.Exists(folder))
        {
            string part = folder + "." + Environment.ProcessId.ToString(CultureInfo.InvariantCulture) + ".part";
            if (Directory.Exists(part))
            {
                Directory.Delete(part, recursive: true);
            }

            string root = Path.GetFullPath(part) + Path.DirectorySeparatorChar;
            foreach (var f in files)
            {
                string target = Path.GetFullPath(Path.Combine(part, f.Name));
                if (!target.StartsWith(root, StringComparison.Ordinal))
                {
                    throw new InvalidDataException($"submission {submission.Id}: the kept file {Engine.Messages.MessageText.Quote(f.Name)} leaves its folder");
                }

                Directory.CreateDirectory(Path.GetDirectoryName(target)!);
                File.WriteAllBytes(target, f.Bytes);
            }

            try
            {
                Directory.Move(part, folder);
            }
            catch (IOException) when (Directory.Exists(folder))
            {
                Directory.Delete(part, recursive: true); // another process of this folder made the same copy first
            }
        }

        string spec = Path.Combine(folder, Path.GetFileName(submission.Path));
        _specs[submission.Id] = spec;
        return spec;
    }

    /// <summary>A new file for the replay page of one play of match <paramref name="match"/> (its outputs go to the database with its record: <see cref="Finish"/>).</summary>
    public string PlayingReplay(long match) =>
        Path.Combine(_dataDir, "replays", string.Create(CultureInfo.InvariantCulture, $"match-{match}.{Environment.ProcessId}-{System.Threading.Interlocked.Increment(ref _plays)}.part"));

    /// <summary>
    /// Writes a running match's record once (<see cref="ILadderStore.FinishMatch"/>) with its outputs: the
    /// replay page played to <paramref name="replay"/> (none when the match was not played: a forfeit) and
    /// <paramref name="outputs"/>. The played file is removed; when written, this folder keeps copies.
    /// </summary>
    public bool Finish(long match, string record, string replay, string outputs)
    {
        try
        {
            var files = new List<StoredFile> { StoredFile.Of(Outputs, Encoding.UTF8.GetBytes(outputs)) };
            if (File.Exists(replay))
            {
                files.Add(StoredFile.Of(Replay, File.ReadAllBytes(replay)));
            }

            if (!_store.FinishMatch(match, record, files))
            {
                return false;
            }

            foreach (var f in files)
            {
                string cached = MatchCache(match, f.Name, f.Sha256);
                if (f.Name == Replay)
                {
                    File.Move(replay, cached, overwrite: true);
                }
                else
                {
                    WriteWhole(cached, f.Bytes);
                }
            }

            return true;
        }
        finally
        {
            if (File.Exists(replay))
            {
                File.Delete(replay);
            }
        }
    }

    /// <summary>Whether match <paramref name="match"/> has the file <paramref name="name"/>.</summary>
    public bool Has(long match, string name) => _store.MatchFileHashes(match).Any(h => h.Name == name);

    /// <summary>The bytes of a match's file (from this folder's copy, made when there is none), or null when it has none.</summary>
    public byte[]? Read(long match, string name)
    {
        string? hash = _store.MatchFileHashes(match).Where(h => h.Name == name).Select(h => h.Sha256).FirstOrDefault();
        if (hash is null)
        {
            return null;
        }

        string cached = MatchCache(match, name, hash);
        if (File.Exists(cached))
        {
            return File.ReadAllBytes(cached);
        }

        var file = _store.MatchFile(match, name);
        if (file is null)
        {
            return null; // requeued meanwhile
        }

        WriteWhole(cached, file.Bytes);
        return file.Bytes;
    }

    /// <summary>
    /// Reads a data folder of an older version into the database: the files of every submission that
    /// has none there (its folder becomes its copy), and the replay page and outputs of every finished
    /// match that has none. What is not in the folder stays without files. How many submissions and matches were read.
    /// </summary>
    public (int Submissions, int Matches) Import()
    {
        int submissions = 0, matches = 0;
        foreach (var s in _store.SubmissionsWithoutFiles())
        {
            // An older version kept an upload in submissions/ID, its SPEC a file or folder there.
            string old = Path.Combine(SubmissionsFolder, s.Id.ToString(CultureInfo.InvariantCulture));
            if (!Directory.Exists(old))
            {
                continue;
            }

            Keep(s.Id, old, s.Path);
            submissions++;
        }

        foreach (long id in _store.MatchesWithoutFiles())
        {
            string replay = Path.Combine(_dataDir, "replays", string.Create(CultureInfo.InvariantCulture, $"match-{id}.html"));
            string outputs = Path.Combine(_dataDir, "outputs", string.Create(CultureInfo.InvariantCulture, $"match-{id}.json"));
            var files = new List<StoredFile>();
            foreach (var (name, path) in new[] { (Outputs, outputs), (Replay, replay) })
            {
                if (File.Exists(path))
                {
                    files.Add(StoredFile.Of(name, File.ReadAllBytes(path)));
                }
            }

            if (files.Count > 0 && _store.AddMatchFiles(id, files))
            {
                matches++;
                foreach (var (f, path) in files.Select(f => (f, f.Name == Replay ? replay : outputs)))
                {
                    File.Move(path, MatchCache(id, f.Name, f.Sha256), overwrite: true);
                }
            }
        }

        return (submissions, matches);
    }

    // A submission's copy: submissions/ID-HASH, HASH over its files' names and hashes.
    private string SubmissionFolder(long submission, IReadOnlyList<StoredFile> files)
    {
        string hash = StoredFile.Hash(Encoding.UTF8.GetBytes(string.Concat(files.OrderBy(f => f.Name, StringComparer.Ordinal).Select(f => f.Name + "\0" + f.Sha256 + "\n"))));
        return Path.Combine(SubmissionsFolder, string.Create(CultureInfo.InvariantCulture, $"{submission}-{hash[..16]}"));
    }

    // A match file's copy: replays/match-ID-HASH.html or outputs/match-ID-HASH.json.
    private string MatchCache(long match, string name, string sha256) =>
        name == Replay
            ? Path.Combine(_dataDir, "replays", string.Create(CultureInfo.InvariantCulture, $"match-{match}-{sha256[..16]}.html"))
            : Path.Combine(_dataDir, "outputs", string.Create(CultureInfo.InvariantCulture, $"match-{match}-{sha256[..16]}.json"));

    // Every file under a folder, by its path there ('/' between folders), in order.
    private static List<StoredFile> Read(string folder) =>
        [.. Directory.GetFiles(folder, "*", SearchOption.AllDirectories)
            .Select(f => StoredFile.Of(Path.GetRelativePath(folder, f).Replace(Path.DirectorySeparatorChar, '/'), File.ReadAllBytes(f)))
            .OrderBy(f => f.Name, StringComparer.Ordinal)];

    // Written beside and moved into place, so a reader sees the whole file or none.
    private static void WriteWhole(string path, byte[] bytes)
    {
        Directory.CreateDirectory(Path.GetDirectoryName(path)!);
        string part = path + "." + Environment.ProcessId.ToString(CultureInfo.InvariantCulture) + "." + Environment.CurrentManagedThreadId.ToString(CultureInfo.InvariantCulture) + ".part";
        File.WriteAllBytes(part, bytes);
        File.Move(part, path, overwrite: true);
    }
}
