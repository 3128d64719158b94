namespace URWPGSim2D.Server.Tests.Hosting;

/// <summary>
/// Deleting what a strategy left in its folder never fails a match: folders nested beyond the path
/// limit, names that are not UTF-8, folders without permissions. Such trees are made with the
/// system's shell (which passes names as bytes) and checked gone with it.
/// </summary>
[Collection(InProcessStaticsCollection.Name)] // sets HostSandbox.Warn
public sealed class RunFolderTests : IDisposable
{
    private readonly string _folder = Directory.CreateTempSubdirectory("urwpg-runfolder-").FullName;

    public void Dispose() => Sh($"chmod -R u+rwx '{_folder}'; rm -rf '{_folder}'");

    private static string Sh(string script)
    {
        var start = new ProcessStartInfo("/bin/sh") { RedirectStandardOutput = true, RedirectStandardError = true, UseShellExecute = false };
        start.ArgumentList.Add("-c");
        start.ArgumentList.Add(script);
        using var p = Process.Start(start)!;
        string output = p.StandardOutput.ReadToEnd() + p.StandardError.ReadToEnd();
        p.WaitForExit();
        return output;
    }

    // A tree no .NET path can name: 300 folders of 50 characters deep, a file with a name that is not
    // UTF-8 at the bottom and at the top, and a folder without any permission holding a file.
    private static string Nasty(string parent)
    {
        string root = Path.Combine(parent, "nasty");
        Sh($"""
            set -e
            mkdir '{root}' && cd '{root}'
            touch "$(printf 'bad\377\376name')"
            mkdir locked && touch locked/inside && chmod 000 locked
            i=0; while [ $i -lt 300 ]; do mkdir {new string('d', 50)} && cd {new string('d', 50)}; i=$((i+1)); done
            touch "$(printf 'deep\377')"
            """);
        return root;
    }

    [Attack("faults", "it buries its scratch folder")]
    [Fact]
    public void A_folder_of_any_depth_names_and_permissions_is_deleted_without_a_warning()
    {
        string root = Nasty(_folder);
        Assert.Equal("yes", Sh($"[ -d '{root}/locked' ] && echo yes").Trim()); // made as meant
        var warnings = new List<string>();
        var before = HostSandbox.Warn;
        HostSandbox.Warn = warnings.Add;
        try
        {
            RunFolder.Delete(root);
        }
        finally
        {
            HostSandbox.Warn = before;
        }

        Assert.Empty(warnings);
        Assert.Equal("gone", Sh($"[ -e '{root}' ] || echo gone").Trim());
    }

    [Attack("faults", "it buries its scratch folder")]
    [Fact]
    public void A_folder_that_cannot_be_deleted_is_one_warning_line_not_an_exception()
    {
        // A folder the system refuses to remove: a mount point (as root), else one in a folder
        // without write permission. What is inside it is deleted all the same.
        string parent = Path.Combine(_folder, "parent");
        string stuck = Path.Combine(parent, "stuck");
        Directory.CreateDirectory(stuck);
        bool root = Sh("id -u").Trim() == "0";
        Assert.Equal(string.Empty, Sh(root ? $"mount -t tmpfs -o size=1m tmpfs '{stuck}'" : $"chmod 555 '{parent}'"));
        try
        {
            File.WriteAllText(Path.Combine(stuck, "inside.txt"), "x");
            var warnings = new List<string>();
            var before = HostSandbox.Warn;
            HostSandbox.Warn = warnings.Add;
            try
            {
                RunFolder.Delete(stuck);
            }
            finally
            {
                HostSandbox.Warn = before;
            }

            string warning = Assert.Single(warnings);
            Assert.StartsWith($"warning: cannot delete the temporary folder {stuck}: ", warning, StringComparison.Ordinal);
            Assert.DoesNotContain('\n', warning);
            Assert.False(File.Exists(Path.Combine(stuck, "inside.txt")));
        }
        finally
        {
            Sh(root ? $"umount '{stuck}'" : $"chmod 755 '{parent}'");
        }
    }

    [Attack("faults", "it buries its scratch folder")]
    [Fact]
    public void A_strategy_that_buries_its_scratch_folder_does_not_fail_the_match_and_leaves_nothing()
    {
        // Without bubblewrap the scratch folder is on the disk: the strategy reports where it is.
        string source = SdkStrategy.Write(_folder, "Burier", "Burier", """
            if (s.Cycle != 0) return;
            var p = new ProcessStartInfo("/bin/sh") { UseShellExecute = false };
            p.ArgumentList.Add("-c");
            p.ArgumentList.Add("touch \"$(printf 'bad\\377')\"; mkdir locked; touch locked/x; chmod 000 locked; i=0; while [ $i -lt 200 ]; do mkdir dddddddddddddddddddddddddddddddddddddddddddddddd && cd dddddddddddddddddddddddddddddddddddddddddddddddd; i=$((i+1)); done");
            Process.Start(p)!.WaitForExit();
            throw new Exception("at=" + Directory.GetCurrentDirectory() + ";");
            """, usings: "using System; using System.IO; using System.Diagnostics; using URWPGSim2D.Strategies;");
        var run = CliRun.Of(string.Empty, "run", "--cycles", "3", "--strategy", "0=" + source, "--strategy-timeout", "1000", "--sandbox", "off");
        Assert.True(run.ExitCode == 0, run.Stderr);
        Assert.DoesNotContain("warning: cannot delete", run.Stderr, StringComparison.Ordinal);
        int at = run.Stdout.IndexOf("at=", StringComparison.Ordinal);
        Assert.True(at >= 0, run.Stdout);
        string scratch = run.Stdout[(at + 3)..run.Stdout.IndexOf(';', at)];
        Assert.Contains("scratch-", scratch, StringComparison.Ordinal);
        Assert.Equal("gone", Sh($"[ -e '{scratch}' ] || echo gone").Trim());
    }

    [Attack("faults", "it buries its scratch folder")]
    [Fact]
    public void Folders_of_servers_that_no_longer_run_are_deleted_the_others_kept()
    {
        // A dead server's folder (buried, as a strategy may leave it), a running one's, one whose lock
        // a server in another PID namespace still holds, this process's own, and strangers.
        string dead = Path.Combine(_folder, "urwpgsim2d-400001-0123456789abcdef0123456789");
        Directory.CreateDirectory(dead);
        Nasty(dead);
        string running = Path.Combine(_folder, "urwpgsim2d-400002-0123456789abcdef0123456789");
        string locked = Path.Combine(_folder, "urwpgsim2d-400003-0123456789abcdef0123456789");
        string own = Path.Combine(_folder, $"urwpgsim2d-{Environment.ProcessId}-0123456789abcdef01234");
        string[] kept = [running, locked, own, Path.Combine(_folder, "urwpgsim2d-notapid-1"), Path.Combine(_folder, "other-400001-1")];
        foreach (string folder in kept)
        {
            Directory.CreateDirectory(folder);
        }

        using (var held = new FileStream(Path.Combine(locked, ".lock"), FileMode.CreateNew, FileAccess.ReadWrite, FileShare.None))
        {
            Assert.Equal(1, RunFolder.SweepStale(_folder, pid => pid == 400002));
        }

        Assert.Equal(string.Empty, Sh($"ls -d '{dead}' 2>/dev/null"));
        foreach (string folder in kept)
        {
            Assert.True(Directory.Exists(folder), folder);
        }

        // Once its lock is let go, the folder of the other namespace's server is left behind too.
        Assert.Equal(1, RunFolder.SweepStale(_folder, pid => pid == 400002));
        Assert.False(Directory.Exists(locked));
    }
}
