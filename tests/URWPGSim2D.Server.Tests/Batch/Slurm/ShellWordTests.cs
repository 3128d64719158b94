namespace URWPGSim2D.Server.Tests.Batch.Slurm;

/// <summary>
/// <see cref="ShellWord"/>: bash reads every quoted word back as exactly the string it came from,
/// whatever it holds (spaces, both quotes, <c>$</c>, backquotes, backslashes, globs, line breaks).
/// </summary>
public sealed class ShellWordTests() : TempFolderTest("urwpg-shellword-")
{
    private static readonly string[] Nasty =
    [
        string.Empty, " ", "a b", "it's", "'", "''", "\"", "\"'\"", "$HOME", "${x}", "$(id)", "`id`", "\\", "\\'", "a\\nb",
        "a\nb", "tab\there", "*", "?", "[ab]", "~", "~root", "-n", "-e", "--x=y", "=a", "a=b", "!", "!!", "#c", ";", "&&",
        "|", "<in", ">out", "()", "{a,b}", "%a", "%%", "é ü 中", "/tmp/my results/it's \"q\" $y/shard-%a.txt",
    ];

    [Theory]
    [InlineData("--batch", "--batch")]
    [InlineData("/usr/share/dotnet/dotnet", "/usr/share/dotnet/dotnet")]
    [InlineData("0=My.dll", "0=My.dll")]
    [InlineData("", "''")]
    [InlineData("a b", "'a b'")]
    [InlineData("it's", "'it'\\''s'")]
    [InlineData("$x", "'$x'")]
    [InlineData("=a", "'=a'")]
    public void PlainWordsStayBareAndTheRestIsSingleQuoted(string value, string word) => Assert.Equal(word, ShellWord.Quote(value));

    [Fact]
    public void BashReadsEveryNastyWordBackUnchanged() => AssertRoundTrip(Nasty);

    [Fact]
    public void BashReadsRandomWordsBackUnchanged()
    {
        const string alphabet = "ab Z09 '\"\\$`!*?[]{}()<>|&;#~=%,:@+-_./\n\té中";
        for (int seed = 1; seed <= 5; seed++)
        {
            var random = new Random(seed);
            string[] words = Enumerable.Range(0, 60).Select(_ =>
            {
                var s = new StringBuilder();
                int length = random.Next(0, 12);
                for (int k = 0; k < length; k++)
                {
                    s.Append(alphabet[random.Next(alphabet.Length)]);
                }

                return s.ToString();
            }).ToArray();
            AssertRoundTrip(words, $"seed {seed}");
        }
    }

    private void AssertRoundTrip(string[] words, string what = "the nasty words")
    {
        string recorder = Bash.Recorder(Path.Combine(Folder, "record"));
        string record = Path.Combine(Folder, "calls");
        File.Delete(record);
        string script = Path.Combine(Folder, "script.sh");
        File.WriteAllText(script, ShellWord.Quote(recorder) + " " + string.Join(" ", words.Select(ShellWord.Quote)) + "\n");
        var (code, _, stderr) = Bash.Run(script, Folder, new() { ["RECORD"] = record });
        Assert.True(code == 0, $"{what}: bash exited {code}: {stderr}");
        var call = Assert.Single(Bash.Records(record));
        for (int i = 0; i < words.Length; i++)
        {
            Assert.True(i + 1 < call.Length && call[i + 1] == words[i], $"{what}: word {i} {System.Text.Json.JsonSerializer.Serialize(words[i])} came back as {(i + 1 < call.Length ? System.Text.Json.JsonSerializer.Serialize(call[i + 1]) : "nothing")}");
        }

        Assert.Equal(words.Length + 1, call.Length);
    }
}
