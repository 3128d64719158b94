using URWPGSim2D.Tournament.Batch;

namespace URWPGSim2D.Server.Cli;

/// <summary>
/// <c>merge [--out FILE] FILE...</c>: combines the result files of every shard of one batch. It
/// checks that they belong to the same batch, that every shard is there once and that every match
/// is there once, then prints the batch's aggregate and, with <c>--out</c>, writes the whole
/// batch's result file (byte-identical to the file of the same batch played in one run).
/// </summary>
internal sealed class MergeCommand : ICliCommand
{
    private static readonly Option<bool> HelpOption = CliSyntax.Help();
    private static readonly Option<string> OutOption = CliSyntax.Value("--out", "FILE", "the merged result file to write", CliCompletions.Paths);
    private static readonly Option<bool> ForceOption = CliSyntax.Flag("--force", "replace an existing --out file");

    /// <inheritdoc/>
    public Command Syntax { get; } = CliSyntax.Command("merge", "Combine the result files of a sharded batch.", Line, HelpOption);

    private static readonly UsageLine Line = new(UsageLine.Optional(OutOption, UsageLine.Optional(ForceOption)), UsageLine.Repeated(FileArgument.Declare("a shard's result file")));

    private static string Usage => "merge " + Line.Text;

    /// <inheritdoc/>
    public string Name => "merge";

    /// <inheritdoc/>
    public string Synopsis => Usage;

    /// <inheritdoc/>
    public string Summary => "Combine the result files of a sharded batch (run --batch --shard --results) and print the aggregate.";

    /// <inheritdoc/>
    public int Run(IReadOnlyList<CommandLineWord> words, CliConsole console)
    {
        string? output = null;
        bool force = false;
        var files = new List<string>();
        foreach (var word in words)
        {
            if (word.Option == HelpOption)
            {
                console.Out.Write($"Usage: {CliApp.ProgramName} {Usage}\n\n{Summary}\nFormat and cluster recipes: docs/batch.md.\n");
                return ExitCodes.Success;
            }

            if (word.Option == OutOption)
            {
                if (output is not null || word.Value is null)
                {
                    throw UsageError(output is null ? "--out needs a value" : "--out given twice");
                }

                output = word.Value;
            }
            else if (word.Option == ForceOption)
            {
                force = !force ? true : throw UsageError("--force given twice");
            }
            else if (word.Text.StartsWith("--", StringComparison.Ordinal))
            {
                throw CliUsageException.UnknownOption("merge", word.Text, Syntax, CliApp.ProgramName + " " + Usage);
            }
            else
            {
                files.Add(word.Text);
            }
        }

        if (files.Count == 0)
        {
            throw UsageError("expected at least one result FILE");
        }

        OutputFile.CheckNew("--out", output, force);

        BatchHeader header;
        List<MatchResult> results;
        try
        {
            (header, results) = Combine(files);
        }
        catch (ResultFileException e)
        {
            console.ErrorLine(e.Message);
            return ExitCodes.BadInput;
        }

        if (output is not null)
        {
            try
            {
                ResultFile.Write(output, header, results);
            }
            catch (Exception e) when (e is IOException or UnauthorizedAccessException or ArgumentException or NotSupportedException)
            {
                console.ErrorLine($"--out: cannot write {output} ({e.Message})");
                return ExitCodes.BadInput;
            }
        }

        console.Out.Write(BatchSummary.Aggregate(header, results));
        RunCommand.Wrote(console, output, string.Create(System.Globalization.CultureInfo.InvariantCulture, $"the results of {results.Count} matches"));
        return ExitCodes.Success;
    }

    /// <summary>Checks the shard files and combines them into the whole batch, in match order.</summary>
    /// <exception cref="ResultFileException">The files are not the complete shards of one batch.</exception>
    public static (BatchHeader Header, List<MatchResult> Results) Combine(IReadOnlyList<string> files)
    {
        BatchHeader? whole = null;
        string? firstFile = null;
        int shards = 0;
        var shardFile = new Dictionary<int, string>();
        var all = new List<MatchResult>();
        foreach (string file in files)
        {
            var (header, results) = ResultFile.Read(file);
            if (whole is null)
            {
                whole = header.Whole;
                firstFile = file;
                shards = header.ShardCount;
            }
            else if (header.Whole != whole || header.ShardCount != shards)
            {
                string why = header.ShardCount != shards ? $"{header.ShardCount} vs {shards} shards" : BatchHeader.Difference(whole, header.Whole);
                throw new ResultFileException($"{file}: belongs to another batch than {firstFile} ({why})");
            }

            if (!shardFile.TryAdd(header.ShardIndex, file))
            {
                throw new ResultFileException($"{file}: shard {header.ShardIndex}/{header.ShardCount} is also in {shardFile[header.ShardIndex]}");
            }

            foreach (var r in results)
            {
                if (r.Index < 0 || r.Index >= header.Matches || !header.Holds(r.Index))
                {
                    throw new ResultFileException($"{file}: match {r.Index} is not in shard {header.ShardIndex}/{header.ShardCount} of {header.Matches} matches");
                }
            }

            if (results.Count != header.ShardMatches)
            {
                throw new ResultFileException($"{file}: shard {header.ShardIndex}/{header.ShardCount} should hold {header.ShardMatches} matches, it holds {results.Count}");
            }

            all.AddRange(results);
        }

        var missing = Enumerable.Range(0, shards).Where(i => !shardFile.ContainsKey(i)).ToArray();
        if (missing.Length > 0)
        {
            throw new ResultFileException($"missing shard{(missing.Length > 1 ? "s" : string.Empty)} {string.Join(", ", missing)} of {shards} (give every shard's result file)");
        }

        all.Sort((a, b) => a.Index.CompareTo(b.Index));
        for (int i = 0; i < all.Count; i++)
        {
            if (all[i].Index != i)
            {
                throw new ResultFileException(i > 0 && all[i].Index == all[i - 1].Index ? $"match {all[i].Index} appears twice" : $"match {i} is missing");
            }
        }

        return (whole!, all);
    }

    private static CliUsageException UsageError(string message) => new("merge: " + message, CliApp.ProgramName + " " + Usage);
}
