namespace URWPGSim2D.Server.Tests.Batch.Slurm;

/// <summary>Runs a script with bash, the shell Slurm runs the generated scripts with: the independent judge of their quoting.</summary>
internal static class Bash
{
    /// <summary>Runs <c>bash SCRIPT</c> in <paramref name="directory"/> with extra environment variables; returns exit code, stdout, stderr.</summary>
    public static (int Code, string Stdout, string Stderr) Run(string script, string directory, Dictionary<string, string?>? environment = null)
    {
        var start = new ProcessStartInfo("bash")
        {
            WorkingDirectory = directory,
            RedirectStandardOutput = true,
            RedirectStandardError = true,
            UseShellExecute = false,
        };
        start.ArgumentList.Add(script);
        foreach (var (name, value) in environment ?? new Dictionary<string, string?>())
        {
            start.Environment[name] = value;
        }

        Process process;
        try
        {
            process = Process.Start(start)!;
        }
        catch (System.ComponentModel.Win32Exception e)
        {
            throw new InvalidOperationException("these tests need bash on PATH (the shell of the Slurm scripts): " + e.Message, e);
        }

        using (process)
        {
            var error = process.StandardError.ReadToEndAsync();
            string output = process.StandardOutput.ReadToEnd();
            Assert.True(process.WaitForExit(120_000), "bash did not finish within 120 s");
            return (process.ExitCode, output, error.Result);
        }
    }

    /// <summary>A bash script that appends to the file <c>$RECORD</c> its argument count, working directory and arguments, NUL-separated; then prints <paramref name="stdout"/>.</summary>
    public static string Recorder(string path, string stdout = "")
    {
        File.WriteAllText(path, "#!/bin/bash\nprintf '%s\\0' \"$#\" \"$PWD\" \"$@\" >> \"$RECORD\"\n" + stdout);
        if (!OperatingSystem.IsWindows())
        {
            File.SetUnixFileMode(path, UnixFileMode.UserRead | UnixFileMode.UserWrite | UnixFileMode.UserExecute);
        }

        return path;
    }

    /// <summary>The calls a <see cref="Recorder"/> recorded: per call, the working directory then the arguments.</summary>
    public static List<string[]> Records(string file)
    {
        string[] fields = File.ReadAllText(file).Split('\0');
        Assert.Equal(string.Empty, fields[^1]);
        var calls = new List<string[]>();
        for (int i = 0; i < fields.Length - 1;)
        {
            int count = int.Parse(fields[i], System.Globalization.CultureInfo.InvariantCulture);
            calls.Add(fields[(i + 1)..(i + 2 + count)]);
            i += 2 + count;
        }

        return calls;
    }
}
